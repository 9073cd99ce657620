/* Shared by the Hubo CAN tests (Modules/hubo_can/tests/can_proto_test.c,
 * Platforms/Hubo/tests/hubo_emu_test.c): a frame written out by hand, F(id, dlc, byte...), so an
 * expected frame never comes from the encoder under test. */
#ifndef HUBO_CAN_FRAME_BY_HAND_H
#define HUBO_CAN_FRAME_BY_HAND_H

#include <stdarg.h>
#include <string.h>

#include "hubo_can/can_proto.h"

static hcan_frame F(uint32_t id, int dlc, ...) {
  hcan_frame f;
  memset(&f, 0, sizeof f);
  f.id = id;
  f.dlc = (uint8_t)dlc;
  va_list ap;
  va_start(ap, dlc);
  for (int i = 0; i < dlc; i++) f.data[i] = (uint8_t)va_arg(ap, int);
  va_end(ap);
  return f;
}

#endif
