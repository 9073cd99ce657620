/* fake_socketcan: SocketCAN raw sockets over a userspace bus (fake_socketcan.c says what it serves). */
#ifndef HRP_FAKE_SOCKETCAN_H
#define HRP_FAKE_SOCKETCAN_H

#include "../hio_sys.h"

/* The fake's calls, in hio_sys.h's shape: a program puts them into its system-call table. */
extern const hio_sys fakecan_sys;

#endif
