/* teamcomm: robocup.humanoid.Message <-> tc_message through protobuf-c (see teamcomm.h). */
#include "teamcomm.h"
#include "robocup.pb-c.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

typedef Robocup__Humanoid__Message PbMessage;
typedef Robocup__Humanoid__Robot PbRobot;
typedef Robocup__Humanoid__Fvec3 PbVec3;
typedef Robocup__Humanoid__Fvec2 PbVec2;
typedef Robocup__Humanoid__Fmat3 PbMat3;

static int fail(char *err, size_t errlen, int code, const char *msg) {
  if (err && errlen) snprintf(err, errlen, "%s", msg);
  return code;
}

size_t tc_message_size(void) { return sizeof(tc_message); }

/* ---- encoding: the protobuf-c structs live on the caller's stack */

typedef struct {
  PbVec3 position;
  PbVec3 cols[3];
  PbMat3 covariance;
  PbRobot robot;
} robot_parts;

static void vec3_set(PbVec3 *v, const float *f) {
  robocup__humanoid__fvec3__init(v);
  v->x = f[0];
  v->y = f[1];
  v->z = f[2];
}

static void mat3_set(PbMat3 *m, PbVec3 cols[3], const float *f) {
  robocup__humanoid__fmat3__init(m);
  vec3_set(&cols[0], f);
  vec3_set(&cols[1], f + 3);
  vec3_set(&cols[2], f + 6);
  m->x = &cols[0];
  m->y = &cols[1];
  m->z = &cols[2];
}

static PbRobot *robot_set(robot_parts *p, const tc_robot *r) {
  robocup__humanoid__robot__init(&p->robot);
  p->robot.player_id = r->player_id;
  p->robot.team = (Robocup__Humanoid__Team)r->team;
  if (r->has_position) {
    vec3_set(&p->position, r->position);
    p->robot.position = &p->position;
  }
  if (r->has_covariance) {
    mat3_set(&p->covariance, p->cols, r->covariance);
    p->robot.covariance = &p->covariance;
  }
  return &p->robot;
}

int tc_encode(const tc_message *m, uint8_t *buf, size_t cap, char *err, size_t errlen) {
  if (!m || !buf) return fail(err, errlen, TC_ERR_ARG, "tc_encode: null argument");
  if (m->n_others > TC_MAX_OTHERS) return fail(err, errlen, TC_ERR_ARG, "tc_encode: n_others > TC_MAX_OTHERS");
  if (m->pose.team < 0 || m->pose.team > TC_TEAM_RED || m->state < 0 || m->state > TC_STATE_PENALISED)
    return fail(err, errlen, TC_ERR_ARG, "tc_encode: team or state out of range");
  PbMessage msg;
  robocup__humanoid__message__init(&msg);
  Google__Protobuf__Timestamp stamp;
  if (m->has_timestamp) {
    google__protobuf__timestamp__init(&stamp);
    stamp.seconds = m->seconds;
    stamp.nanos = m->nanos;
    msg.timestamp = &stamp;
  }
  robot_parts pose, target, others[TC_MAX_OTHERS];
  PbRobot *other_ptrs[TC_MAX_OTHERS];
  if (m->has_pose) msg.pose = robot_set(&pose, &m->pose);
  Robocup__Humanoid__Ball ball;
  PbVec3 ball_pos, ball_vel, ball_cols[3];
  PbMat3 ball_cov;
  if (m->has_ball) {
    robocup__humanoid__ball__init(&ball);
    vec3_set(&ball_pos, m->ball);
    vec3_set(&ball_vel, m->ball_velocity);
    ball.position = &ball_pos;
    ball.velocity = &ball_vel;
    if (m->has_ball_covariance) {
      mat3_set(&ball_cov, ball_cols, m->ball_covariance);
      ball.covariance = &ball_cov;
    }
    msg.ball = &ball;
  }
  for (uint32_t i = 0; i < m->n_others; i++) other_ptrs[i] = robot_set(&others[i], &m->others[i]);
  msg.n_others = m->n_others;
  msg.others = m->n_others ? other_ptrs : NULL;
  PbVec3 walk;
  if (m->has_walk_command) {
    vec3_set(&walk, m->walk_command);
    msg.walk_command = &walk;
  }
  if (m->has_target_pose) msg.target_pose = robot_set(&target, &m->target_pose);
  PbVec2 kick;
  if (m->has_kick_target) {
    robocup__humanoid__fvec2__init(&kick);
    kick.x = m->kick_target[0];
    kick.y = m->kick_target[1];
    msg.kick_target = &kick;
  }
  msg.state = (Robocup__Humanoid__State)m->state;
  msg.fallen = m->fallen != 0;
  size_t n = robocup__humanoid__message__get_packed_size(&msg);
  if (n > cap) return fail(err, errlen, TC_ERR_SPACE, "tc_encode: buffer too small");
  return (int)robocup__humanoid__message__pack(&msg, buf);
}

/* ---- decoding: protobuf-c allocates from a fixed arena (no unbounded allocation) */

typedef struct {
  size_t used;
  _Alignas(16) uint8_t bytes[TC_ARENA];
} arena;

static _Thread_local arena tc_arena;

static void *arena_alloc(void *data, size_t size) {
  arena *a = data;
  size_t need = (size + 15) & ~(size_t)15;
  if (need < size || need > sizeof(a->bytes) - a->used) return NULL;
  void *p = a->bytes + a->used;
  a->used += need;
  return p;
}

static void arena_free(void *data, void *ptr) { (void)data; (void)ptr; } /* all at once: used = 0 */

/* A received float as LuaJIT may see it: a NaN becomes the one quiet NaN. LuaJIT keeps its own
 * values' types in NaN bit patterns, and it converts a float to a number without looking, so a NaN
 * with a chosen payload (e.g. bits ff900001) would reach Lua as a table or a string at a wild
 * address: one datagram would crash the behavior (found by Tests/team/teamcomm_fuzz_test.sh). */
static float canon(float x) { return isnan(x) ? NAN : x; }

static void vec3_get(float *f, const PbVec3 *v) {
  f[0] = v ? canon(v->x) : 0.f;
  f[1] = v ? canon(v->y) : 0.f;
  f[2] = v ? canon(v->z) : 0.f;
}

static int mat3_get(float *f, const PbMat3 *m) {
  if (!m) return 0;
  vec3_get(f, m->x);
  vec3_get(f + 3, m->y);
  vec3_get(f + 6, m->z);
  return 1;
}

/* An enum value this side does not know (a newer message, or garbage) reads as unknown (0), so a
 * decoded message is always one tc_encode takes (found by Tests/team/teamcomm_fuzz_test.sh). */
static int32_t known(int v, int max) { return v >= 0 && v <= max ? v : 0; }

static void robot_get(tc_robot *r, const PbRobot *p) {
  r->player_id = p->player_id;
  r->team = known((int)p->team, TC_TEAM_RED);
  r->has_position = p->position != NULL;
  vec3_get(r->position, p->position);
  r->has_covariance = mat3_get(r->covariance, p->covariance);
}

int tc_decode(const uint8_t *buf, size_t len, tc_message *m, char *err, size_t errlen) {
  if (!buf || !m) return fail(err, errlen, TC_ERR_ARG, "tc_decode: null argument");
  memset(m, 0, sizeof(*m));
  if (len > TC_MAX_SIZE) return fail(err, errlen, TC_ERR_SIZE, "tc_decode: datagram longer than TC_MAX_SIZE");
  tc_arena.used = 0;
  ProtobufCAllocator alloc = { arena_alloc, arena_free, &tc_arena };
  PbMessage *msg = robocup__humanoid__message__unpack(&alloc, len, buf);
  if (!msg) return fail(err, errlen, TC_ERR_DECODE, "tc_decode: not a robocup.humanoid.Message");
  if (msg->timestamp) {
    m->has_timestamp = 1;
    m->seconds = msg->timestamp->seconds;
    m->nanos = msg->timestamp->nanos;
  }
  if (msg->pose) {
    m->has_pose = 1;
    robot_get(&m->pose, msg->pose);
  }
  if (msg->ball) {
    m->has_ball = 1;
    vec3_get(m->ball, msg->ball->position);
    vec3_get(m->ball_velocity, msg->ball->velocity);
    m->has_ball_covariance = mat3_get(m->ball_covariance, msg->ball->covariance);
  }
  m->others_total = (uint32_t)msg->n_others;
  m->n_others = msg->n_others < TC_MAX_OTHERS ? (uint32_t)msg->n_others : TC_MAX_OTHERS;
  for (uint32_t i = 0; i < m->n_others; i++) robot_get(&m->others[i], msg->others[i]);
  if (msg->walk_command) {
    m->has_walk_command = 1;
    vec3_get(m->walk_command, msg->walk_command);
  }
  if (msg->target_pose) {
    m->has_target_pose = 1;
    robot_get(&m->target_pose, msg->target_pose);
  }
  if (msg->kick_target) {
    m->has_kick_target = 1;
    m->kick_target[0] = canon(msg->kick_target->x);
    m->kick_target[1] = canon(msg->kick_target->y);
  }
  m->state = known((int)msg->state, TC_STATE_PENALISED);
  m->fallen = msg->fallen ? 1 : 0;
  tc_arena.used = 0; /* nothing of the arena is kept */
  return 0;
}
