/* The fake SocketCAN (Platforms/Hubo/tests/fake_socketcan.c, linked in and called through its
 * system-call table, as the DCM's test build and the emulator call it) behaves as the kernel's CAN_RAW sockets do for what the Hubo DCM uses: interface
 * indices, bind, delivery to the other sockets of the interface only, filters (also inverted),
 * error frames through the error mask, non-blocking reads, poll, bad frame sizes, another
 * process on the bus, an interface taken down and back up. TAP. */
#include "fake_socketcan.h"
#include "tap.h"

#include <errno.h>
#include <linux/can.h>
#include <linux/can/error.h>
#include <linux/can/raw.h>
#include <net/if.h>
#include <poll.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/ioctl.h>
#include <sys/socket.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

/* the calls under test */
static const hio_sys *const C = &fakecan_sys;

/* The index of interface `name` (SIOCGIFINDEX on socket s), or -1 with errno set. */
static int ifindex(int s, const char *name) {
  struct ifreq ifr;
  memset(&ifr, 0, sizeof ifr);
  snprintf(ifr.ifr_name, sizeof ifr.ifr_name, "%s", name);
  return C->ioctl(s, SIOCGIFINDEX, &ifr) < 0 ? -1 : ifr.ifr_ifindex;
}

/* poll through the fake's ppoll */
static int poll_ms(struct pollfd *p, nfds_t n, int ms) {
  struct timespec ts = { ms / 1000, (long)(ms % 1000) * 1000000L };
  return C->ppoll(p, n, &ts, NULL);
}

static int open_can(const char *name) {
  const int s = C->socket(PF_CAN, SOCK_RAW | SOCK_NONBLOCK, CAN_RAW);
  if (s < 0) return -1;
  const int idx = ifindex(s, name);
  struct sockaddr_can a = { .can_family = AF_CAN, .can_ifindex = idx };
  if (idx < 0 || C->bind(s, (struct sockaddr *)&a, sizeof a) < 0) {
    C->close(s);
    return -1;
  }
  return s;
}

static int send_id(int s, canid_t id, int dlc) {
  struct can_frame f;
  memset(&f, 0, sizeof f);
  f.can_id = id;
  f.can_dlc = (uint8_t)dlc;
  for (int i = 0; i < dlc; i++) f.data[i] = (uint8_t)(id + i);
  return (int)C->write(s, &f, sizeof f);
}

/* id of the next frame within ms, or -1 */
static long next_id(int s, int ms) {
  struct pollfd p = { .fd = s, .events = POLLIN };
  if (poll_ms(&p, 1, ms) <= 0 || !(p.revents & POLLIN)) return -1;
  struct can_frame f;
  if (C->read(s, &f, sizeof f) != sizeof f) return -2;
  return (long)f.can_id;
}

int main(void) {
  /* the fake reads its environment at its first call */
  char dir[] = "/tmp/fakecan_test_XXXXXX";
  if (!mkdtemp(dir)) { perror("mkdtemp"); return 1; }
  setenv("FAKECAN_DIR", dir, 1);
  unsetenv("FAKECAN_IFACES");
  const int s0 = C->socket(PF_CAN, SOCK_RAW, CAN_RAW);
  check(s0 >= 0 && ifindex(s0, "can0") == 1 && ifindex(s0, "can1") == 2, "can0, can1 have indices 1, 2");
  errno = 0;
  check(s0 >= 0 && ifindex(s0, "nope0") < 0 && errno == ENODEV, "SIOCGIFINDEX of a missing interface: ENODEV");
  C->close(s0);

  const int a = open_can("can0"), b = open_can("can0"), c = open_can("can1");
  check(a >= 0 && b >= 0 && c >= 0, "three sockets bound (two on can0, one on can1)");
  send_id(a, 0x063, 8);
  check(next_id(b, 200) == 0x063, "a frame written on can0 reaches the other can0 socket");
  check(next_id(c, 50) == -1, "not the can1 socket");
  check(next_id(a, 50) == -1, "not the sender");
  struct can_frame f;
  errno = 0;
  check(C->read(b, &f, sizeof f) < 0 && errno == EAGAIN, "non-blocking read of an empty queue: EAGAIN");

  struct can_filter flt[2] = { { 0x063, CAN_SFF_MASK | CAN_EFF_FLAG | CAN_RTR_FLAG }, { 0x150, 0x7F0 } };
  check(C->setsockopt(b, SOL_CAN_RAW, CAN_RAW_FILTER, flt, sizeof flt) == 0, "filters set");
  send_id(a, 0x064, 8);
  check(next_id(b, 50) == -1, "a frame no filter passes is not seen (poll says nothing)");
  send_id(a, 0x064, 8);
  send_id(a, 0x15A, 8);
  send_id(a, 0x063, 8);
  check(next_id(b, 200) == 0x15A && next_id(b, 200) == 0x063, "frames the filters pass arrive in order");
  send_id(a, CAN_EFF_FLAG | 0x063, 8);
  check(next_id(b, 50) == -1, "the mask's EFF bit keeps an extended 0x063 out");
  struct can_filter inv = { CAN_INV_FILTER | 0x001, CAN_SFF_MASK };
  C->setsockopt(b, SOL_CAN_RAW, CAN_RAW_FILTER, &inv, sizeof inv);
  send_id(a, 0x001, 3);
  send_id(a, 0x002, 2);
  check(next_id(b, 200) == 0x002 && next_id(b, 50) == -1, "an inverted filter passes everything but its id");
  C->setsockopt(b, SOL_CAN_RAW, CAN_RAW_FILTER, NULL, 0);
  send_id(a, 0x002, 2);
  check(next_id(b, 50) == -1, "no filters: no frames");
  struct can_filter all = { 0, 0 };
  C->setsockopt(b, SOL_CAN_RAW, CAN_RAW_FILTER, &all, sizeof all);

  send_id(a, CAN_ERR_FLAG | CAN_ERR_PROT, 8);
  check(next_id(b, 50) == -1, "an error frame needs the error mask");
  can_err_mask_t em = CAN_ERR_MASK;
  check(C->setsockopt(b, SOL_CAN_RAW, CAN_RAW_ERR_FILTER, &em, sizeof em) == 0, "error mask set");
  send_id(a, CAN_ERR_FLAG | CAN_ERR_PROT, 8);
  check(next_id(b, 200) == (long)(CAN_ERR_FLAG | CAN_ERR_PROT), "with it, the error frame arrives");

  errno = 0;
  check(C->write(a, "short", 5) < 0 && errno == EINVAL, "a write that is not a struct can_frame: EINVAL");
  memset(&f, 0, sizeof f);
  f.can_dlc = 9;
  errno = 0;
  check(C->write(a, &f, sizeof f) < 0 && errno == EINVAL, "DLC 9: EINVAL");

  /* another process on the bus */
  const pid_t pid = fork();
  if (pid == 0) {
    const int s = open_can("can0");
    for (int k = 0; k < 100; k++) send_id(s, 0x100 + (canid_t)k, 8);
    C->close(s);
    _exit(0);
  }
  int got = 0, inorder = 1;
  for (int k = 0; k < 100; k++) {
    const long id = next_id(b, 1000);
    if (id < 0) break;
    inorder = inorder && id == 0x100 + k;
    got++;
  }
  waitpid(pid, NULL, 0);
  char d[64];
  snprintf(d, sizeof d, "%d of 100", got);
  tap_ok(got == 100 && inorder, "another process's 100 frames arrive, in order", d);

  /* the interface goes down and comes back */
  char down[300];
  snprintf(down, sizeof down, "%s/can0.down", dir);
  FILE *df = fopen(down, "w");
  if (df) fclose(df);
  struct timespec ts = { 0, 30 * 1000 * 1000 };
  nanosleep(&ts, NULL);
  errno = 0;
  const int w = send_id(a, 0x063, 8);
  check(w < 0 && errno == ENETDOWN, "interface down: write fails with ENETDOWN");
  struct pollfd p = { .fd = b, .events = POLLIN };
  check(poll_ms(&p, 1, 100) == 1 && (p.revents & POLLERR), "interface down: poll reports POLLERR");
  unlink(down);
  nanosleep(&ts, NULL);
  send_id(a, 0x063, 8);
  check(next_id(b, 200) == 0x063, "interface up again: frames flow");

  /* a burst as one DCM cycle sends it */
  for (int k = 0; k < 60; k++) send_id(a, 0x010 + (canid_t)(k % 0x30), 6);
  int n = 0;
  while (next_id(b, 50) >= 0) n++;
  snprintf(d, sizeof d, "%d of 60", n);
  tap_ok(n == 60, "a burst of 60 frames arrives whole", d);
  C->close(a);
  C->close(b);
  C->close(c);
  char cmd[400];
  snprintf(cmd, sizeof cmd, "rm -rf '%s'", dir);
  if (system(cmd) != 0) fprintf(stderr, "could not remove %s\n", dir);
  printf("1..%d\n", tap_count);
  return tap_failures ? 1 : 0;
}
