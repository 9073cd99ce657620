/* observer: the recorder in a lockstep run (hrp_record --lockstep). It takes a slot in the sync block as an
 * observer (Lib/lockstep.lua's protocol): at each tick it waits until the other participants due at the
 * tick have finished it, samples every block -- so each tick is recorded whole, with what the robot's
 * processes made of it -- and reports the tick done. The DCM waits for it like for any participant, so
 * nothing is missed; sampling takes tens of microseconds. Without lockstep the recorder only reads. */
#include "record.h"

#include <errno.h>
#include <stdio.h>
#include <string.h>
#include <unistd.h>

#define LOAD(p) __atomic_load_n((p), __ATOMIC_ACQUIRE)

/* Lib/lockstep.lua's STAGE.observer: after motion and vision (0) and the behavior (1) */
#define OBSERVER_STAGE 2

int rec_observer_join(rec_observer *ob, shm_schema *schema, int robot_id, char *err, size_t errlen) {
  memset(ob, 0, sizeof *ob);
  int rc = shm_block_open(schema, "sync", robot_id, SHM_OPEN_CREATE, &ob->blk, err, errlen);
  if (rc < 0) return rc;
  ob->lockstep = (int32_t *)rec_field(ob->blk, "lockstep", SHM_I32, NULL);
  ob->tick = (uint32_t *)rec_field(ob->blk, "tick", SHM_U32, NULL);
  ob->done_count = (uint32_t *)rec_field(ob->blk, "done_count", SHM_U32, NULL);
  ob->pid = (int32_t *)rec_field(ob->blk, "pid", SHM_I32, &ob->n);
  ob->wake = (uint32_t *)rec_field(ob->blk, "wake_tick", SHM_U32, NULL);
  ob->done = (uint32_t *)rec_field(ob->blk, "done_tick", SHM_U32, NULL);
  ob->observer = (int32_t *)rec_field(ob->blk, "observer", SHM_I32, NULL);
  if (!ob->lockstep || !ob->tick || !ob->done_count || !ob->pid || !ob->wake || !ob->done || !ob->observer) {
    snprintf(err, errlen, "recorder: block 'sync' lacks a lockstep field (Config/shm.schema)");
    shm_block_close(ob->blk);
    return -EINVAL;
  }
  const int me = (int)getpid();
  for (int pass = 0; pass < 2; pass++) {
    for (int i = 0; i < ob->n; i++) {
      const int p = LOAD(&ob->pid[i]);
      /* claimed first (the pid negated: Lib/lockstep.lua's protocol), then set up, then shown: the
       * fields of a slot another process won are never written */
      if ((p == 0 || (pass == 1 && !shm_pid_alive(p < 0 ? -p : p))) && shm_cas_i32(&ob->pid[i], p, -me)) {
        ob->done[i] = 0;
        ob->wake[i] = 0;
        ob->observer[i] = OBSERVER_STAGE;
        shm_cas_i32(&ob->pid[i], -me, me);
        ob->slot = i;
        return 0;
      }
    }
  }
  snprintf(err, errlen, "recorder: all %d lockstep slots are taken", ob->n);
  shm_block_close(ob->blk);
  return -EBUSY;
}

uint32_t rec_observer_wait(rec_observer *ob, double timeout_s) {
  const uint32_t tick = LOAD(ob->tick);
  if (LOAD(ob->lockstep) != 1 || tick == 0 || tick == LOAD(&ob->done[ob->slot])) {
    shm_futex_wait(ob->tick, tick, timeout_s);
    return 0;
  }
  /* settle: the lower stages due at this tick first (observers never wait for each other) */
  const double deadline = shm_now() + 5.0;
  while (shm_now() < deadline) {
    const uint32_t seen = LOAD(ob->done_count);
    int waiting = 0;
    for (int i = 0; i < ob->n && !waiting; i++) {
      const int p = LOAD(&ob->pid[i]);
      waiting = i != ob->slot && p > 0 && LOAD(&ob->observer[i]) < OBSERVER_STAGE && LOAD(&ob->wake[i]) <= tick &&
                LOAD(&ob->done[i]) < tick && shm_pid_alive(p);
    }
    if (!waiting) break;
    shm_futex_wait(ob->done_count, seen, 0.01);
  }
  return tick;
}

void rec_observer_done(rec_observer *ob, uint32_t tick) {
  ob->wake[ob->slot] = tick + 1;
  __atomic_store_n(&ob->done[ob->slot], tick, __ATOMIC_RELEASE);
  shm_fetch_add_u32(ob->done_count, 1);
  shm_futex_wake(ob->done_count);
}

void rec_observer_leave(rec_observer *ob) {
  if (!ob->blk) return;
  ob->wake[ob->slot] = 0xffffffffu;
  shm_cas_i32(&ob->pid[ob->slot], (int32_t)getpid(), 0);
  shm_fetch_add_u32(ob->done_count, 1);
  shm_futex_wake(ob->done_count);
  shm_block_close(ob->blk);
  ob->blk = NULL;
}
