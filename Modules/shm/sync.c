/* Sequence lock, futex waits and atomics on shared-memory words. */
#include "shm_internal.h"

#include <errno.h>
#include <linux/futex.h>
#include <math.h>
#include <pthread.h>
#include <sched.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/syscall.h>
#include <time.h>
#include <unistd.h>

/* The seqlock's fences. ThreadSanitizer does not model fences (gcc refuses them under
 * -fsanitize=thread): its builds order the same accesses with a read-modify-write of the sequence
 * word instead (stronger, slower; make SANITIZE=thread only). */
#ifdef __SANITIZE_THREAD__
#define SEQ_FENCE(seq, order) ((void)__atomic_fetch_add((uint32_t *)(seq), 0u, __ATOMIC_ACQ_REL))
#else
#define SEQ_FENCE(seq, order) __atomic_thread_fence(order)
#endif

double shm_now(void) {
  struct timespec ts;
  clock_gettime(CLOCK_MONOTONIC, &ts);
  return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

static void cpu_relax(void) {
#if defined(__x86_64__) || defined(__i386__)
  __builtin_ia32_pause();
#endif
}

int shm_pid_state(int pid, unsigned long long *start) {
  if (start) *start = 0;
  char path[32], buf[512];
  snprintf(path, sizeof path, "/proc/%d/stat", pid);
  FILE *f = pid > 0 ? fopen(path, "r") : NULL;
  if (!f) return 0;
  const size_t n = fread(buf, 1, sizeof buf - 1, f);
  fclose(f);
  buf[n] = 0;
  const char *p = strrchr(buf, ')');   /* "pid (comm) S ...": comm may hold anything */
  if (!p || p[1] != ' ' || !p[2]) return 0;
  const int state = (unsigned char)p[2];
  p += 2;
  for (int field = 3; field < 22 && p; field++) {   /* on to field 22, starttime */
    p = strchr(p, ' ');
    if (p) p++;
  }
  if (start && p) *start = strtoull(p, NULL, 10);
  return state;
}

int shm_pid_stopped(int pid) {
  const int st = shm_pid_state(pid, NULL);
  return st == 'T' || st == 't';
}

/* this process's pid and start time for writer_pid / writer_start, without a system call per write
 * (glibc no longer caches the pid); a forked child finds them afresh */
static int32_t g_pid;
static uint32_t g_start;
static void forget_pid(void) { g_pid = 0; }
static void __attribute__((constructor)) pid_init(void) { pthread_atfork(NULL, NULL, forget_pid); }
static int32_t my_pid(void) {
  if (!g_pid) {
    unsigned long long start;
    g_pid = (int32_t)getpid();
    shm_pid_state(g_pid, &start);
    g_start = (uint32_t)start;
  }
  return g_pid;
}

void shm_write_begin(shm_block *b) {
  shm_header *h = shm_block_header(b);
  uint32_t *seq = &h->seq;
  double stuck_since = 0;
  uint32_t stuck_value = 0;
  for (unsigned spins = 0;; spins++) {
    uint32_t s = __atomic_load_n(seq, __ATOMIC_RELAXED);
    if (!(s & 1u)) {
      if (__atomic_compare_exchange_n(seq, &s, s + 1, 0, __ATOMIC_ACQUIRE, __ATOMIC_RELAXED)) break;
      continue;
    }
    /* Another writer is inside. After ~10 ms at the same value it died mid-update: take over
     * (s+2 stays odd, so readers keep waiting until our shm_write_end). */
    if (spins % 256 == 255) {
      double now = shm_now();
      if (s != stuck_value) { stuck_value = s; stuck_since = now; }
      else if (now - stuck_since > 0.010 &&
               __atomic_compare_exchange_n(seq, &s, s + 2, 0, __ATOMIC_ACQUIRE, __ATOMIC_RELAXED))
        break;
      sched_yield();
    } else {
      cpu_relax();
    }
  }
  /* who is inside, for readers that wait too long (shm_read_begin_checked); set once the lock is
   * ours, so a reader that sees 0 knows only that a writer is just coming in */
  const int32_t me = my_pid();
  __atomic_store_n(&h->writer_start, g_start, __ATOMIC_RELAXED);
  __atomic_store_n(&h->writer_pid, me, __ATOMIC_RELAXED);
  SEQ_FENCE(seq, __ATOMIC_RELEASE);
}

static long futex(volatile uint32_t *addr, int op, uint32_t val, const struct timespec *ts) {
  return syscall(SYS_futex, addr, op, val, ts, NULL, 0);
}

void shm_write_end(shm_block *b) {
  shm_header *h = shm_block_header(b);
  __atomic_store_n(&h->writer_pid, 0, __ATOMIC_RELAXED);
  __atomic_fetch_add(&h->seq, 1u, __ATOMIC_RELEASE);
  __atomic_fetch_add(&h->writes, 1u, __ATOMIC_RELEASE);
  if (__atomic_load_n(&h->waiters, __ATOMIC_ACQUIRE)) futex(&h->writes, FUTEX_WAKE, 0x7fffffff, NULL);
}

/* What became of the writer inside: 'D'ead (gone, a zombie nobody reaped yet, or its pid reused by
 * another process: none of them will ever write again), 'T' stopped, or 0 running. */
static int writer_fate(int pid, uint32_t start) {
  if (!shm_pid_alive(pid)) return 'D';
  unsigned long long now_start;
  const int st = shm_pid_state(pid, &now_start);
  if (st == 0) return shm_pid_alive(pid) ? 0 : 'D';   /* /proc unreadable: kill(0) decides */
  if (st == 'Z' || st == 'X' || st == 'x') return 'D';
  if (start != 0 && (uint32_t)now_start != start) return 'D';
  if (st == 'T' || st == 't') return 'T';
  return 0;
}

int shm_read_begin_checked(const shm_block *b, uint32_t *out, char *err, size_t errlen) {
  shm_header *h = shm_block_header((shm_block *)b);
  const uint32_t *seq = &h->seq;
  uint32_t stuck_value = 0;
  double stuck_since = 0;
  for (unsigned spins = 0;; spins++) {
    uint32_t s = __atomic_load_n(seq, __ATOMIC_ACQUIRE);
    if (!(s & 1u)) {
      *out = s;
      return 0;
    }
    if (spins % 256 != 255) {
      cpu_relax();
      continue;
    }
    if (spins < 16 * 256) {
      sched_yield();
    } else {
      /* still mid-write: the writer was preempted, maybe by this reader. Under SCHED_FIFO a
       * reader above the writer's priority never lets it run on this CPU by yielding (seen: an
       * emulator at FIFO 30 spinning on the sim DCM's block, the DCM at FIFO 20, the other CPU
       * busy: neither moved again), so sleep a little */
      struct timespec ts = { 0, 20000 };
      nanosleep(&ts, NULL);
    }
    /* the same odd value for SHM_STALE_S: is anyone still writing? */
    const double now = shm_now();
    if (s != stuck_value || stuck_since == 0) {
      stuck_value = s;
      stuck_since = now;
    } else if (now - stuck_since > SHM_STALE_S) {
      const int32_t pid = __atomic_load_n(&h->writer_pid, __ATOMIC_RELAXED);
      const uint32_t start = __atomic_load_n(&h->writer_start, __ATOMIC_RELAXED);
      const int fate = pid > 0 ? writer_fate(pid, start) : 0;
      if (fate && __atomic_load_n(seq, __ATOMIC_ACQUIRE) == s) {
        *out = s;
        if (err && errlen)
          snprintf(err, errlen, "block '%s' is stale: its writer (pid %d) %s mid-update", h->block, (int)pid,
                   fate == 'T' ? "is stopped" : "died");
        return fate == 'T' ? -EAGAIN : -EOWNERDEAD;
      }
      stuck_since = now;   /* running (or not yet known): look again in a while */
    }
  }
}

uint32_t shm_read_begin(const shm_block *b) {
  uint32_t s;
  char err[160];
  if (shm_read_begin_checked(b, &s, err, sizeof err) < 0) {
    /* said once per stuck sequence value of a block: a reader polling it is not a flood */
    static __thread const void *said_block;
    static __thread uint32_t said_seq;
    if (said_block != b || said_seq != s) fprintf(stderr, "shm: %s: read as it is\n", err);
    said_block = b;
    said_seq = s;
  }
  return s;
}

int shm_read_retry(const shm_block *b, uint32_t s) {
  uint32_t *seq = &shm_block_header((shm_block *)b)->seq;
  SEQ_FENCE(seq, __ATOMIC_ACQUIRE);
  return __atomic_load_n(seq, __ATOMIC_RELAXED) != s;
}

static struct timespec to_timespec(double s) {
  if (!(s > 0)) s = 0;
  struct timespec ts;
  ts.tv_sec = (time_t)s;
  ts.tv_nsec = (long)((s - (double)ts.tv_sec) * 1e9);
  return ts;
}

uint32_t shm_wait_write(shm_block *b, uint32_t last, double timeout_s) {
  shm_header *h = shm_block_header(b);
  double deadline = shm_now() + timeout_s;
  __atomic_fetch_add(&h->waiters, 1u, __ATOMIC_ACQ_REL);
  uint32_t now_w;
  while ((now_w = __atomic_load_n(&h->writes, __ATOMIC_ACQUIRE)) == last) {
    double left = deadline - shm_now();
    if (left <= 0) break;
    struct timespec ts = to_timespec(left);
    futex(&h->writes, FUTEX_WAIT, last, &ts);
  }
  __atomic_fetch_sub(&h->waiters, 1u, __ATOMIC_ACQ_REL);
  return now_w;
}

int shm_futex_wait(volatile uint32_t *addr, uint32_t val, double timeout_s) {
  struct timespec ts = to_timespec(timeout_s);
  long r = futex(addr, FUTEX_WAIT, val, isinf(timeout_s) ? NULL : &ts);
  return r == 0 ? 0 : -errno;
}

int shm_futex_wake(volatile uint32_t *addr) {
  return (int)futex(addr, FUTEX_WAKE, 0x7fffffff, NULL);
}

int shm_cas_i32(volatile int32_t *addr, int32_t expected, int32_t desired) {
  return __atomic_compare_exchange_n(addr, &expected, desired, 0, __ATOMIC_ACQ_REL,
                                     __ATOMIC_ACQUIRE);
}

uint32_t shm_fetch_add_u32(volatile uint32_t *addr, uint32_t delta) {
  return __atomic_fetch_add(addr, delta, __ATOMIC_ACQ_REL);
}

void shm_store_release_u32(volatile uint32_t *addr, uint32_t val) {
  __atomic_store_n(addr, val, __ATOMIC_RELEASE);
}

uint32_t shm_load_acquire_u32(const volatile uint32_t *addr) {
  return __atomic_load_n(addr, __ATOMIC_ACQUIRE);
}
