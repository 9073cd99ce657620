/* The C side of the latency benchmark (Tools/bench/shm_latency.lua writes from Lua):
 *   shm_latency_reader N DATA_FIFO ACK_FIFO
 * Phase 1: N updates of the `bench` block, each observed by spinning on the block's write
 * counter; latency = now - t_send written by Lua; acknowledged through bench.ack.
 * Phase 2: N 8-byte messages through a pipe (blocking read), acknowledged through a second pipe.
 * Prints p50/p99/max for both and their ratio. */
#include "shm/shm.h"

#include <fcntl.h>
#include <sched.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

static int cmp(const void *a, const void *b) {
  double x = *(const double *)a, y = *(const double *)b;
  return (x > y) - (x < y);
}

static void stats(const char *name, double *v, long n, double out[3]) {
  qsort(v, (size_t)n, sizeof *v, cmp);
  out[0] = v[n / 2] * 1e6;
  out[1] = v[(long)(0.99 * (double)(n - 1))] * 1e6;
  out[2] = v[n - 1] * 1e6;
  printf("%-5s one-way latency over %ld updates: p50 %.3f us  p99 %.3f us  max %.3f us\n", name, n,
         out[0], out[1], out[2]);
}

/* Real-time priority on its own core, as a DCM would run, so other load on the machine does not
 * measure itself into the figures. Says what it got. */
static void go_realtime(int cpu) {
  cpu_set_t set;
  CPU_ZERO(&set);
  CPU_SET(cpu, &set);
  int pinned = sched_setaffinity(0, sizeof set, &set) == 0;
  struct sched_param sp = {.sched_priority = 10};
  int rt = sched_setscheduler(0, SCHED_FIFO, &sp) == 0;
  printf("reader: %s, %s\n", pinned ? "pinned to cpu 1" : "not pinned",
         rt ? "SCHED_FIFO" : "normal priority (no permission for SCHED_FIFO)");
}

int main(int argc, char **argv) {
  if (argc < 4) { fprintf(stderr, "usage: shm_latency_reader N DATA_FIFO ACK_FIFO\n"); return 2; }
  go_realtime(1);
  long n = atol(argv[1]);
  char err[512];
  shm_block *b = NULL;
  if (shm_block_open(NULL, "bench", shm_robot_id(), SHM_OPEN_CREATE, &b, err, sizeof err) < 0) {
    fprintf(stderr, "%s\n", err);
    return 2;
  }
  volatile uint32_t *k = shm_field_ptr(b, "k", NULL, NULL);
  volatile double *t_send = shm_field_ptr(b, "t_send", NULL, NULL);
  volatile uint32_t *ack = shm_field_ptr(b, "ack", NULL, NULL);
  double *lat = malloc(sizeof(double) * (size_t)n);
  uint32_t seen = shm_block_header(b)->writes;
  /* Tell the writer we are ready. */
  __atomic_store_n(ack, 0xffffffffu, __ATOMIC_RELEASE);
  for (long i = 0; i < n; i++) {
    uint32_t w;
    unsigned spins = 0;
    while ((w = __atomic_load_n(&shm_block_header(b)->writes, __ATOMIC_ACQUIRE)) == seen) {
      if (++spins % 4096 == 0) sched_yield();   /* let a loaded machine make progress */
    }
    double now = shm_now();
    uint32_t seq, kk;
    double ts;
    do {
      seq = shm_read_begin(b);
      ts = *t_send;
      kk = *k;
    } while (shm_read_retry(b, seq));
    seen = w;
    lat[i] = now - ts;
    __atomic_store_n(ack, kk, __ATOMIC_RELEASE);
  }
  double s[3], p[3];
  stats("shm", lat, n, s);

  int data = open(argv[2], O_RDONLY);
  int ackfd = open(argv[3], O_WRONLY);
  if (data < 0 || ackfd < 0) { perror("open fifo"); return 2; }
  for (long i = 0; i < n; i++) {
    double ts;
    if (read(data, &ts, sizeof ts) != (ssize_t)sizeof ts) { fprintf(stderr, "short pipe read\n"); return 2; }
    lat[i] = shm_now() - ts;
    char c = 1;
    if (write(ackfd, &c, 1) != 1) return 2;
  }
  stats("pipe", lat, n, p);
  printf("ratio pipe/shm: p50 %.1fx  p99 %.1fx\n", p[0] / s[0], p[1] / s[1]);
  printf("goal: shm p99 < 2 us (%s), >= 10x better than the pipe at p99 (%s)\n",
         s[1] < 2.0 ? "met" : "not met", p[1] / s[1] >= 10.0 ? "met" : "not met");
  free(lat);
  shm_block_close(b);
  return 0;
}
