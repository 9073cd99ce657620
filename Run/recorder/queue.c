/* queue: the sampler -> writer queue, bounded in bytes; a full queue drops the new item (counted), or in
 * lockstep waits for room. */
#include "record.h"

#include <stdlib.h>
#include <time.h>

void rec_queue_init(rec_queue *q, size_t cap) {
  pthread_mutex_init(&q->mu, NULL);
  pthread_condattr_t ca;
  pthread_condattr_init(&ca);
  pthread_condattr_setclock(&ca, CLOCK_MONOTONIC);
  pthread_cond_init(&q->cv, &ca);
  pthread_cond_init(&q->room, &ca);
  pthread_condattr_destroy(&ca);
  q->head = q->tail = NULL;
  q->bytes = 0;
  q->cap = cap;
  q->dropped = 0;
  q->closed = 0;
}

int rec_queue_push(rec_queue *q, rec_item *it) {
  pthread_mutex_lock(&q->mu);
  /* an empty queue takes any item, so that one larger than the cap cannot wait for ever */
  while (q->wait_for_room && !q->closed && q->bytes > 0 && q->bytes + it->len > q->cap)
    pthread_cond_wait(&q->room, &q->mu);
  if (q->bytes + it->len > q->cap || q->closed) {
    q->dropped++;
    pthread_mutex_unlock(&q->mu);
    free(it);
    return -1;
  }
  it->next = NULL;
  if (q->tail) q->tail->next = it;
  else q->head = it;
  q->tail = it;
  q->bytes += it->len;
  /* the writer is woken once per sample, at its tick-end mark, not for each of its messages (a wake-up
   * per message was a context switch per block per tick); in lockstep, where the sampler may wait for
   * room, for each */
  if (it->kind == REC_ITEM_TICK_END || q->wait_for_room) pthread_cond_signal(&q->cv);
  pthread_mutex_unlock(&q->mu);
  return 0;
}

rec_item *rec_queue_pop(rec_queue *q, double timeout_s) {
  struct timespec until;
  clock_gettime(CLOCK_MONOTONIC, &until);
  until.tv_sec += (time_t)timeout_s;
  until.tv_nsec += (long)((timeout_s - (double)(time_t)timeout_s) * 1e9);
  if (until.tv_nsec >= 1000000000L) {
    until.tv_sec++;
    until.tv_nsec -= 1000000000L;
  }
  pthread_mutex_lock(&q->mu);
  while (!q->head && !q->closed)
    if (pthread_cond_timedwait(&q->cv, &q->mu, &until) != 0) break;
  rec_item *it = q->head;
  if (it) {
    q->head = it->next;
    if (!q->head) q->tail = NULL;
    q->bytes -= it->len;
    pthread_cond_signal(&q->room);
  }
  pthread_mutex_unlock(&q->mu);
  return it;
}

void rec_queue_tick_end(rec_queue *q) {
  rec_item *it = (rec_item *)calloc(1, sizeof *it);
  if (!it) return;
  it->kind = REC_ITEM_TICK_END;
  rec_queue_push(q, it);   /* 0 bytes: takes no room; a closed queue frees it */
}

void rec_queue_close(rec_queue *q) {
  pthread_mutex_lock(&q->mu);
  q->closed = 1;
  pthread_cond_broadcast(&q->cv);
  pthread_cond_broadcast(&q->room);
  pthread_mutex_unlock(&q->mu);
}

uint64_t rec_queue_dropped(rec_queue *q) {
  pthread_mutex_lock(&q->mu);
  const uint64_t d = q->dropped;
  pthread_mutex_unlock(&q->mu);
  return d;
}
