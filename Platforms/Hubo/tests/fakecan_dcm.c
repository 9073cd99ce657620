/* The test build of the Hubo DCM (build/testbin/dcm_hubo_fakecan, which ./run_dcm starts when
 * HUBO_FAKE_CAN=1): dcm_hubo's objects with the fake SocketCAN in hubo_io's system-call table,
 * set before main so the DCM's code stays that of dcm_hubo. */
#include "../hubo_io.h"
#include "fake_socketcan.h"

__attribute__((constructor)) static void use_fake_can(void) { hio_sys_calls = fakecan_sys; }
