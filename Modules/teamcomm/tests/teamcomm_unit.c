/* teamcomm unit test: our encoder and decoder agree, and bad input is refused without harm.
 * (The cross-check against Python's protobuf and the league's schema: Tests/team/.) */
#include "teamcomm/teamcomm.h"
#include "tap.h"

#include <math.h>
#include <stdlib.h>

static int near(float a, float b) { return fabsf(a - b) < 1e-6f; }

int main(void) {
  char err[160];
  uint8_t buf[TC_MAX_SIZE + 64];
  tc_message m, d;
  memset(&m, 0, sizeof m);
  m.has_timestamp = 1; m.seconds = 1700000000; m.nanos = 250000000;
  m.has_pose = 1; m.pose.player_id = 3; m.pose.team = TC_TEAM_RED; m.pose.has_position = 1;
  m.pose.position[0] = -1.25f; m.pose.position[1] = 0.5f; m.pose.position[2] = 3.0f;
  m.pose.has_covariance = 1;
  for (int i = 0; i < 9; i++) m.pose.covariance[i] = (float)i * 0.01f;
  m.has_ball = 1; m.ball[0] = 2.0f; m.ball[1] = -0.75f; m.ball_velocity[0] = 0.3f;
  m.n_others = 2;
  m.others[0].player_id = 0; m.others[0].team = TC_TEAM_BLUE; m.others[0].has_position = 1;
  m.others[0].position[0] = 1.0f;
  m.others[1].player_id = 4; m.others[1].team = TC_TEAM_RED;
  m.has_walk_command = 1; m.walk_command[0] = 0.2f; m.walk_command[2] = -0.1f;
  m.has_target_pose = 1; m.target_pose.has_position = 1; m.target_pose.position[0] = 1.5f;
  m.has_kick_target = 1; m.kick_target[0] = 4.5f;
  m.state = TC_STATE_PENALISED;

  int n = tc_encode(&m, buf, sizeof buf, err, sizeof err);
  tap_ok(n > 0 && n < 200, "encodes a full message", err);
  int rc = tc_decode(buf, (size_t)n, &d, err, sizeof err);
  check(rc == 0, "decodes it");
  check(d.has_timestamp && d.seconds == 1700000000 && d.nanos == 250000000, "timestamp");
  check(d.has_pose && d.pose.player_id == 3 && d.pose.team == TC_TEAM_RED && near(d.pose.position[0], -1.25f)
        && near(d.pose.position[1], 0.5f) && near(d.pose.position[2], 3.0f), "pose");
  check(d.pose.has_covariance && near(d.pose.covariance[8], 0.08f) && near(d.pose.covariance[3], 0.03f),
        "pose covariance, column by column");
  check(d.has_ball && near(d.ball[0], 2.0f) && near(d.ball[1], -0.75f) && near(d.ball_velocity[0], 0.3f)
        && !d.has_ball_covariance, "ball, no covariance");
  check(d.n_others == 2 && d.others_total == 2 && d.others[0].has_position && !d.others[1].has_position
        && d.others[1].player_id == 4, "others");
  check(d.has_walk_command && near(d.walk_command[2], -0.1f) && d.has_target_pose
        && near(d.target_pose.position[0], 1.5f) && d.has_kick_target && near(d.kick_target[0], 4.5f),
        "walk command, target pose, kick target");
  check(d.state == TC_STATE_PENALISED, "state");

  tc_message empty;
  memset(&empty, 0, sizeof empty);
  n = tc_encode(&empty, buf, sizeof buf, err, sizeof err);
  check(n == 0 && tc_decode(buf, 0, &d, err, sizeof err) == 0 && !d.has_pose && !d.has_ball,
        "an empty message is zero bytes and decodes to nothing set");

  check(tc_encode(&m, buf, 10, err, sizeof err) == TC_ERR_SPACE, "a too small buffer is refused");
  m.state = 7;
  check(tc_encode(&m, buf, sizeof buf, err, sizeof err) == TC_ERR_ARG, "an out-of-range state is refused");
  m.state = TC_STATE_UNPENALISED;

  /* truncations of a valid message, and random bytes: decoded or refused, never a crash */
  n = tc_encode(&m, buf, sizeof buf, err, sizeof err);
  int refused = 0;
  for (int k = 1; k < n; k++)
    if (tc_decode(buf, (size_t)k, &d, err, sizeof err) == TC_ERR_DECODE) refused++;
  tap_ok(refused > n / 2, "most truncations are refused", NULL);
  srand(7);
  int garbage_refused = 0;
  for (int k = 0; k < 2000; k++) {
    uint8_t g[300];
    size_t len = (size_t)(rand() % 300);
    for (size_t i = 0; i < len; i++) g[i] = (uint8_t)rand();
    if (tc_decode(g, len, &d, err, sizeof err) < 0) garbage_refused++;
  }
  tap_ok(garbage_refused > 1500, "random bytes are refused", NULL);
  memset(buf, 0, sizeof buf);
  check(tc_decode(buf, TC_MAX_SIZE + 1, &d, err, sizeof err) == TC_ERR_SIZE, "an oversized datagram is refused");

  /* many others: kept up to TC_MAX_OTHERS, all counted; beyond the arena's room: refused */
  size_t len = 0;
  while (len < 200) { /* field 4 (others), length 0: an empty Robot, 2 bytes each */
    buf[len++] = 0x22;
    buf[len++] = 0x00;
  }
  rc = tc_decode(buf, len, &d, err, sizeof err);
  tap_ok(rc == 0 && d.n_others == TC_MAX_OTHERS && d.others_total == 100, "100 others: 16 kept, 100 counted", err);
  while (len + 2 <= TC_MAX_SIZE) {
    buf[len++] = 0x22;
    buf[len++] = 0x00;
  }
  rc = tc_decode(buf, len, &d, err, sizeof err);
  tap_ok(rc == TC_ERR_DECODE, "1024 others need more than the fixed arena: refused", err);
  n = tc_encode(&m, buf, sizeof buf, err, sizeof err);
  check(tc_decode(buf, (size_t)n, &d, err, sizeof err) == 0 && d.pose.player_id == 3,
        "and the next message decodes again");

  /* found by Tests/team/teamcomm_fuzz_test.sh: a NaN's payload reached Lua, where LuaJIT read the
   * bits ff900001 as a table at a wild address (a crash); every NaN decodes to the one quiet NaN */
  uint32_t hostile = 0xff900001u, quiet = 0x7fc00000u, got[4];
  memcpy(&m.pose.position[0], &hostile, 4);
  memcpy(&m.ball[1], &hostile, 4);
  memcpy(&m.walk_command[2], &hostile, 4);
  memcpy(&m.kick_target[0], &hostile, 4);
  n = tc_encode(&m, buf, sizeof buf, err, sizeof err);
  rc = tc_decode(buf, (size_t)n, &d, err, sizeof err);
  memcpy(&got[0], &d.pose.position[0], 4);
  memcpy(&got[1], &d.ball[1], 4);
  memcpy(&got[2], &d.walk_command[2], 4);
  memcpy(&got[3], &d.kick_target[0], 4);
  check(rc == 0 && got[0] == quiet && got[1] == quiet && got[2] == quiet && got[3] == quiet,
        "a NaN with a payload decodes to the quiet NaN (pose, ball, walk, kick target)");

  /* found by the same fuzzer: a state or team value beyond the enum was passed on as it was (a
   * message tc_encode refuses, a number where Lua expects a name); both read as unknown now */
  m.pose.position[0] = 1.0f;
  n = tc_encode(&m, buf, sizeof buf, err, sizeof err);
  tap_ok(n > 2 && buf[n - 2] == 0x40, "the state is the last field (tag 0x40)", NULL);
  buf[n - 1] = 0x3f;   /* state 63 */
  rc = tc_decode(buf, (size_t)n, &d, err, sizeof err);
  check(rc == 0 && d.state == TC_STATE_UNKNOWN, "a state beyond the enum reads as unknown");
  tc_message bad_team;
  memset(&bad_team, 0, sizeof bad_team);
  bad_team.has_pose = 1;
  bad_team.pose.team = TC_TEAM_RED;
  n = tc_encode(&bad_team, buf, sizeof buf, err, sizeof err);   /* pose { team = 2 }: 0a 02 20 02 */
  tap_ok(n == 4 && buf[2] == 0x20, "a pose holding only its team", NULL);
  buf[3] = 0x09;
  rc = tc_decode(buf, (size_t)n, &d, err, sizeof err);
  check(rc == 0 && d.has_pose && d.pose.team == TC_TEAM_UNKNOWN, "a team beyond the enum reads as unknown");

  check(tc_message_size() == sizeof(tc_message), "tc_message_size");
  return tap_done();
}
