/* lockstep: the DCM side of the sync block. Participants (Lib/lockstep.lua) claim a slot with their
 * pid (negated while they set the slot up: not a participant yet, but not free either); the DCM publishes tick N and waits until every live participant whose wake_tick <= N
 * reports done_tick >= N. Participants that died without leaving are dropped. */
#include "dcm.h"

#define LOAD32(p) __atomic_load_n((p), __ATOMIC_ACQUIRE)

void dcm_lockstep_start(dcm_lockstep *l, uint32_t tick) {
  for (int r = 0; r < l->n; r++) {
    dcm_blk_sync *y = l->sync[r];
    /* a participant registered with an earlier DCM: consult it from the first tick on */
    for (int k = 0; k < y->n.pid; k++)
      if (y->pid[k] > 0 && y->wake_tick[k] != 0xffffffffu && y->wake_tick[k] > tick) y->wake_tick[k] = tick;
    *y->lockstep = 1;
  }
}

void dcm_lockstep_end(dcm_lockstep *l) {
  for (int r = 0; r < l->n; r++) {
    *l->sync[r]->lockstep = 0;
    shm_futex_wake(l->sync[r]->tick);
  }
}

void dcm_lockstep_publish(dcm_lockstep *l, uint32_t tick) {
  for (int r = 0; r < l->n; r++) {
    shm_store_release_u32(l->sync[r]->tick, tick);
    shm_futex_wake(l->sync[r]->tick);
  }
}

/* 1 if at least `need` participants (alive) have slots, over all robots. */
static int joined(const dcm_lockstep *l, uint32_t tick, int need) {
  int n = 0;
  for (int r = 0; r < l->n; r++) {
    const dcm_blk_sync *y = l->sync[r];
    for (int k = 0; k < y->n.pid; k++) {
      const int pid = LOAD32(&y->pid[k]);
      /* one that answered the last tick needs no system call to prove it is alive */
      if (pid > 0 && (LOAD32(&y->done_tick[k]) + 1 >= tick || shm_pid_alive(pid)) && ++n >= need) return 1;
    }
  }
  return 0;
}

static int stopped(const dcm_lockstep *l, int pid) {
  dcm_proc p;
  return (l->probe ? l->probe : dcm_proc_probe)(pid, &p) == 0 && (p.state == 'T' || p.state == 't');
}

/* Slot of a participant robot r still waits for at `tick`, or -1. */
static int pending(const dcm_lockstep *l, int r, uint32_t tick) {
  const dcm_blk_sync *y = l->sync[r];
  for (int k = 0; k < y->n.pid; k++) {
    const int32_t pid = LOAD32(&y->pid[k]);
    if (pid <= 0) continue;
    if (k < DCM_SYNC_MAX && l->skip[r][k] == pid) continue;
    if (LOAD32(&y->wake_tick[k]) > tick) continue;
    if (LOAD32(&y->done_tick[k]) >= tick) continue;
    return k;
  }
  return -1;
}

int dcm_lockstep_hold(dcm_lockstep *l, uint32_t tick, void (*idle)(void *ctx, int alone), void *ctx,
                      volatile sig_atomic_t *stop) {
  if (l->started || l->start_with <= 1) return 0;
  while (!joined(l, tick, l->start_with)) {
    if (stop && *stop) return 1;
    if (idle) idle(ctx, 1);
    shm_futex_wait(l->sync[0]->done_count, shm_load_acquire_u32(l->sync[0]->done_count), 0.02);
  }
  return 0;
}

int dcm_lockstep_wait(dcm_lockstep *l, uint32_t tick, void (*idle)(void *ctx, int alone), void *ctx,
                      volatile sig_atomic_t *stop) {
  /* nobody anywhere: hold the clock until one joins (a run starts on a defined tick and burns no
   * CPU meanwhile) */
  const int need = !l->started && l->start_with > 1 ? l->start_with : 1;
  while (!joined(l, tick, need)) {
    if (stop && *stop) return 1;
    if (idle) idle(ctx, 1);
    shm_futex_wait(l->sync[0]->done_count, shm_load_acquire_u32(l->sync[0]->done_count), 0.02);
  }
  l->started = 1;
  for (int r = 0; r < l->n; r++) {
    dcm_blk_sync *y = l->sync[r];
    /* one passed over is waited for again once it runs (SIGCONT): it catches up on the tick */
    for (int k = 0; k < y->n.pid && k < DCM_SYNC_MAX; k++)
      if (l->skip[r][k] && (l->skip[r][k] != LOAD32(&y->pid[k]) || !stopped(l, l->skip[r][k]))) l->skip[r][k] = 0;
    const double start = shm_now();
    double since = start, looked = 0;
    for (;;) {
      if (stop && *stop) return 1;
      if (idle) idle(ctx, 0);
      const uint32_t c = shm_load_acquire_u32(y->done_count);
      const int due = pending(l, r, tick);
      if (due < 0) break;
      /* a stopped participant would hold the clock (and every other participant) until it is
       * continued; the DCM's guard trips when it is the robot's motion (its tick_ack stands still) */
      if (l->stall_after > 0 && due < DCM_SYNC_MAX && shm_now() - start > l->stall_after &&
          shm_now() - looked > l->stall_after / 2) {
        looked = shm_now();
        const int32_t pid = LOAD32(&y->pid[due]);
        if (pid != 0 && stopped(l, pid)) {
          l->skip[r][due] = pid;
          l->passed++;
          continue;
        }
      }
      if (shm_now() - since > l->drop_after) {
        for (int k = 0; k < y->n.pid; k++) {
          const int pid = LOAD32(&y->pid[k]);
          /* a claim (a negative pid) is dropped only when its claimant died */
          if (pid != 0 && !shm_pid_alive(pid < 0 ? -pid : pid) && shm_cas_i32(&y->pid[k], pid, 0)) l->dropped++;
        }
        since = shm_now();
      }
      /* participants usually answer within tens of microseconds: polling a little before sleeping
       * saves the DCM's own wake-up latency on every tick */
      const double spin_until = shm_now() + l->spin;
      while (shm_load_acquire_u32(y->done_count) == c && shm_now() < spin_until) {
#if defined(__x86_64__) || defined(__i386__)
        for (int k = 0; k < 64; k++) __builtin_ia32_pause();
#endif
      }
      double nap = 0.05;
      if (l->stall_after > 0 && l->stall_after < nap) nap = l->stall_after;   /* to look at a stall in time */
      if (shm_load_acquire_u32(y->done_count) == c) shm_futex_wait(y->done_count, c, nap);
    }
  }
  return 0;
}
