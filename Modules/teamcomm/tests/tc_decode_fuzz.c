/* libFuzzer target: the team message decoder (tc_decode, protobuf-c underneath) on any datagram.
 * Checks: at most TC_MAX_OTHERS robots kept, and a decoded message encodes and decodes back to the
 * same message (nothing read is lost or invented; others_total becomes the kept count; floats
 * compare as numbers: -0 is sent as 0, proto3's default). */
#include "teamcomm.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

static tc_message m, again;
static uint8_t out[4 * TC_MAX_SIZE];

static int feq(const float *a, const float *b, int n) {
  for (int i = 0; i < n; i++)
    if (!(a[i] == b[i] || (isnan(a[i]) && isnan(b[i])))) return 0;
  return 1;
}

static int robot_eq(const tc_robot *a, const tc_robot *b) {
  return a->player_id == b->player_id && a->team == b->team && a->has_position == b->has_position &&
         feq(a->position, b->position, 3) && a->has_covariance == b->has_covariance &&
         feq(a->covariance, b->covariance, 9);
}

static int message_eq(const tc_message *a, const tc_message *b) {
  int eq = a->has_timestamp == b->has_timestamp && a->seconds == b->seconds && a->nanos == b->nanos &&
           a->has_pose == b->has_pose && robot_eq(&a->pose, &b->pose) && a->has_ball == b->has_ball &&
           feq(a->ball, b->ball, 3) && feq(a->ball_velocity, b->ball_velocity, 3) &&
           a->has_ball_covariance == b->has_ball_covariance && feq(a->ball_covariance, b->ball_covariance, 9) &&
           a->n_others == b->n_others && a->has_walk_command == b->has_walk_command &&
           feq(a->walk_command, b->walk_command, 3) && a->has_target_pose == b->has_target_pose &&
           robot_eq(&a->target_pose, &b->target_pose) && a->has_kick_target == b->has_kick_target &&
           feq(a->kick_target, b->kick_target, 2) && a->state == b->state;
  for (uint32_t i = 0; eq && i < a->n_others; i++) eq = robot_eq(&a->others[i], &b->others[i]);
  return eq;
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size) {
  /* an exact-size heap copy: ASan sees any read past the end */
  uint8_t *buf = malloc(size ? size : 1);
  if (!buf) return 0;
  memcpy(buf, data, size);
  char err[160];
  int rc = tc_decode(buf, size, &m, err, sizeof err);
  free(buf);
  if (rc != 0) {
    if (rc != TC_ERR_SIZE && rc != TC_ERR_DECODE) abort();
    return 0;
  }
  if (m.n_others > TC_MAX_OTHERS || m.n_others > m.others_total) abort();
  int n = tc_encode(&m, out, sizeof out, err, sizeof err);
  if (n < 0) abort();
  if (tc_decode(out, (size_t)n, &again, err, sizeof err) != 0) abort();
  if (again.others_total != m.n_others || !message_eq(&m, &again)) abort();
  return 0;
}
