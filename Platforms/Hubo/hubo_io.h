/* hubo_io: one SocketCAN raw socket per bus (AF_CAN, CAN_RAW): open with filters for the boards'
 * replies and the controller's error frames, a send queue that waits when the kernel's queue is
 * full (ENOBUFS / EAGAIN) instead of dropping, receive into the bus's hcan_net, and the wire
 * counts for the statistics. A bus whose interface goes down or away is closed and reopened. */
#ifndef HRP_HUBO_IO_H
#define HRP_HUBO_IO_H

#include <stdint.h>

#include "hio_sys.h"
#include "hubo_can/can_proto.h"

#define HIO_TXQ 256

typedef struct hio_bus {
  char iface[64];
  int fd;                        /* -1 while closed */
  hcan_net net;                  /* the boards on it, the host's view */
  hcan_frame txq[HIO_TXQ];
  int txn, txhead;
  /* counts since start */
  uint64_t tx_frames, rx_frames, tx_bits, rx_bits;
  uint32_t tx_dropped;           /* frames the queue could not hold */
  uint32_t downs;                /* times the bus went away */
  double reopen_at;              /* s, next attempt while closed */
} hio_bus;

/* hubo_io's system calls (hio_sys.h): the libc functions; only a test build of the DCM changes
 * them, before it opens a bus. */
extern hio_sys hio_sys_calls;

void hio_init(hio_bus *b, const char *iface);
/* Opens the socket (non-blocking, bound, filtered). 0, or a negative errno with a message. */
int hio_open(hio_bus *b, char *err, size_t errlen);
void hio_close(hio_bus *b);
/* Queues a frame (sent by hio_flush). */
void hio_queue(hio_bus *b, const hcan_frame *f);
/* Sends queued frames until the kernel's queue is full. Returns 0, or a negative errno when the
 * bus is gone (ENETDOWN, ENODEV, ...): the caller closes it. */
int hio_flush(hio_bus *b);
/* Reads every frame waiting into the bus's net. Returns frames read, or a negative errno when
 * the bus is gone. */
int hio_receive(hio_bus *b);
/* Waits until `deadline` (monotonic s) or until every bus has nothing owed and nothing to send;
 * flushes and receives on the way. Returns the number of buses that failed (closed by it). */
int hio_settle(hio_bus *buses, int n, double deadline);
/* Monotonic seconds. */
double hio_now(void);

#endif
