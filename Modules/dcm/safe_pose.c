/* safe_pose: the pose a body's safe state moves into (robot.lua `safe_pose`), for the guard. */
#include "dcm.h"

#include <math.h>
#include <stdio.h>

int dcm_safe_pose_load(const char *robot, int nj, dcm_safe_pose *out, char *err, size_t errlen) {
  for (int j = 0; j < DCM_NJ_MAX; j++) out->q[j] = NAN;
  out->ramp = 0;
  out->hardness = NAN;
  dcm_config *c;
  int r = dcm_config_load("robot", robot, NULL, &c, err, errlen);
  if (r < 0) return r;
  if (!dcm_config_has(c, "safe_pose")) {
    dcm_config_free(c);
    return 0;
  }
  static char names[DCM_NJ_MAX][DCM_NAME_MAX];
  int n = dcm_config_strs(c, "joints", names, 1, DCM_NJ_MAX, err, errlen);
  r = n < 0 ? n : dcm_config_num(c, "safe_pose.ramp", &out->ramp, err, errlen);
  if (r == 0 && out->ramp < 0)
    r = dcm_config_fail(c, err, errlen, "safe_pose.ramp must be >= 0 s, not %g", out->ramp);
  if (r == 0 && dcm_config_has(c, "safe_pose.hardness")) {
    r = dcm_config_num(c, "safe_pose.hardness", &out->hardness, err, errlen);
    if (r == 0 && !(out->hardness >= 0 && out->hardness <= 1))
      r = dcm_config_fail(c, err, errlen, "safe_pose.hardness must be within 0..1, not %g", out->hardness);
  }
  int posed = 0;
  for (int j = 0; r == 0 && j < n && j < nj; j++) {
    char key[DCM_NAME_MAX + 16];
    snprintf(key, sizeof key, "safe_pose.q.%s", names[j]);
    if (dcm_config_has(c, key)) {
      r = dcm_config_num(c, key, &out->q[j], err, errlen);
      posed++;
    }
  }
  dcm_config_free(c);
  return r < 0 ? r : posed;
}
