/* teamcomm: the RoboCup Humanoid League's standard team message (robocup.proto, package
 * robocup.humanoid) encoded and decoded with protobuf-c, behind plain structs for the LuaJIT FFI
 * (Player/Team/teamcomm.lua).
 *
 * Decoding is bounded: a datagram longer than TC_MAX_SIZE is refused, protobuf-c allocates from a
 * fixed arena (TC_ARENA bytes, per thread; a message needing more is refused as malformed), and at
 * most TC_MAX_OTHERS of the sender's seen robots are kept (others_total counts them all).
 * Functions return 0 (or a length) on success and a negative code with a message in err. */
#ifndef TEAMCOMM_H
#define TEAMCOMM_H

#include <stddef.h>
#include <stdint.h>

#define TC_MAX_SIZE 2048   /* bytes: a larger datagram is no team message (ours are ~150 bytes) */
#define TC_ARENA 65536     /* bytes protobuf-c may allocate while decoding one message */
#define TC_MAX_OTHERS 16   /* robots seen by the sender kept per message */

/* Team (enum robocup.humanoid.Team) and State */
enum { TC_TEAM_UNKNOWN = 0, TC_TEAM_BLUE = 1, TC_TEAM_RED = 2 };
enum { TC_STATE_UNKNOWN = 0, TC_STATE_UNPENALISED = 1, TC_STATE_PENALISED = 2 };

/* error codes */
enum { TC_ERR_SIZE = -1, TC_ERR_DECODE = -2, TC_ERR_SPACE = -3, TC_ERR_ARG = -4 };

typedef struct {
  uint32_t player_id;      /* 0: unknown */
  int32_t team;            /* TC_TEAM_* */
  int32_t has_position;
  float position[3];       /* m, m, rad: x, y, heading on the field */
  int32_t has_covariance;
  float covariance[9];     /* column vectors x, y, z of the message's fmat3, one after the other */
} tc_robot;

typedef struct {
  int32_t has_timestamp;
  int64_t seconds;         /* google.protobuf.Timestamp */
  int32_t nanos;
  int32_t has_pose;
  tc_robot pose;           /* the sender */
  int32_t has_ball;
  float ball[3];           /* m, field frame */
  float ball_velocity[3];  /* m/s */
  int32_t has_ball_covariance;
  float ball_covariance[9];
  uint32_t n_others;       /* kept in others[] (<= TC_MAX_OTHERS) */
  uint32_t others_total;   /* in the message */
  tc_robot others[TC_MAX_OTHERS];
  int32_t has_walk_command;
  float walk_command[3];   /* m/s, m/s, rad/s, the sender's frame */
  int32_t has_target_pose;
  tc_robot target_pose;
  int32_t has_kick_target;
  float kick_target[2];
  int32_t state;           /* TC_STATE_* */
  int32_t fallen;          /* 0/1: our extension field (101), the sender is down */
} tc_message;

/* Encodes m into buf (cap bytes); returns the length, or a negative code. */
int tc_encode(const tc_message *m, uint8_t *buf, size_t cap, char *err, size_t errlen);

/* Decodes len bytes into m (every field set: absent ones zero, has_* 0); 0 or a negative code. */
int tc_decode(const uint8_t *buf, size_t len, tc_message *m, char *err, size_t errlen);

/* sizeof(tc_message), for the FFI's check that its declaration matches. */
size_t tc_message_size(void);

#endif
