/* collide: self-collision of a body on its URDF's collision geometry (coal through Pinocchio's
 * geometry model), behind a C ABI for LuaJIT (Lib/collide.lua). The body is built with a fixed base:
 * only the links' places relative to each other matter.
 *
 * Pairs: every pair of collision objects on different links, less the pairs of links one joint
 * apart (their boxes overlap at the joint by construction), the pairs collide_ignore_near drops
 * (links a few joints apart) and the pairs collide_ignore_at drops (those that touch at a reference
 * pose, as a robot's SRDF does: shapes that overlap where the body stands are the shapes'
 * approximation, not a collision).
 *
 * Errors: every function returns >= 0 on success and < 0 on failure with a message in
 * collide_error(). Joint angles are in the caller's joint order (robot.lua `joints`), radians.
 */
#ifndef HRP_COLLIDE_H
#define HRP_COLLIDE_H

#include <stddef.h>

#ifdef __cplusplus
extern "C" {
#endif

typedef struct collide collide;

int collide_new(const char *urdf, int njoint, const char *const *joints, collide **out, char *err, size_t errlen);
void collide_free(collide *c);
const char *collide_error(const collide *c);
int collide_npair(const collide *c);                 /* pairs checked */
/* Drops the pairs whose objects are closer than `margin` at q (njoint angles): returns how many. */
int collide_ignore_at(collide *c, const double *q);
/* Drops the pairs of links at most `joints` joints apart along the body's tree (a hip's or a
 * shoulder's three axes meet at a point: the boxes of the links around them overlap whatever the
 * angles): returns how many. */
int collide_ignore_near(collide *c, int joints);
/* Objects closer than margin (m, >= 0) count as colliding. */
int collide_set_margin(collide *c, double margin);
/* The number of pairs in collision at q (0: none). The first one's index into *first (may be NULL). */
int collide_check(collide *c, const double *q, int *first);
/* A pair's link names (side 0 or 1); NULL if out of range. */
const char *collide_pair_link(const collide *c, int pair, int side);
/* Microseconds of CPU the last collide_check took. */
double collide_check_us(const collide *c);

#ifdef __cplusplus
}
#endif

#endif /* HRP_COLLIDE_H */
