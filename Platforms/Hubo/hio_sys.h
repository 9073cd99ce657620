/* hio_sys: the system calls a program makes on its SocketCAN sockets, as a table, so a test can put
 * a fake SocketCAN in their place in its own process (Platforms/Hubo/tests/fake_socketcan.c: this
 * kernel has no AF_CAN), where a sanitizer sees the fake and the program together. In production
 * the table holds the libc functions themselves (HIO_SYS_LIBC): a call costs one indirect jump on
 * top of the system call. */
#ifndef HRP_HIO_SYS_H
#define HRP_HIO_SYS_H

#include <poll.h>
#include <signal.h>
#include <sys/ioctl.h>
#include <sys/socket.h>
#include <sys/types.h>
#include <time.h>
#include <unistd.h>

typedef struct hio_sys {
  int (*socket)(int domain, int type, int protocol);
  int (*ioctl)(int fd, unsigned long req, ...);
  int (*bind)(int fd, const struct sockaddr *addr, socklen_t len);
  int (*setsockopt)(int fd, int level, int name, const void *val, socklen_t len);
  ssize_t (*read)(int fd, void *buf, size_t len);
  ssize_t (*write)(int fd, const void *buf, size_t len);
  int (*ppoll)(struct pollfd *fds, nfds_t n, const struct timespec *timeout, const sigset_t *mask);
  int (*close)(int fd);
} hio_sys;

#define HIO_SYS_LIBC { socket, ioctl, bind, setsockopt, read, write, ppoll, close }

#endif
