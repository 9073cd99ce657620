/* packets: the UDP datagrams the behavior read (the net.packets ring, Lib/netlog.lua) as messages of
 * their own channels, /gamecontroller and /team.message (hrp/msg/Packet: the bytes as they arrived).
 * Each sample takes the datagrams written since the last one; more than the ring holds in between
 * (npacket, 16) are lost and counted. */
#include "record.h"

#include <errno.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

int rec_packets_open(rec_packets *p, shm_schema *schema, int robot_id, char *err, size_t errlen) {
  memset(p, 0, sizeof *p);
  int rc = shm_block_open(schema, REC_PACKETS_BLOCK, robot_id, SHM_OPEN_CREATE, &p->blk, err, errlen);
  if (rc < 0) return rc;
  int bytes = 0, n2 = 0, n3 = 0, n4 = 0, n5 = 0;
  p->count = (const uint32_t *)rec_field(p->blk, "written", SHM_U32, NULL);
  p->source = (const int32_t *)rec_field(p->blk, "source", SHM_I32, &p->slots);
  p->length = (const int32_t *)rec_field(p->blk, "length", SHM_I32, &n2);
  p->time = (const double *)rec_field(p->blk, "time", SHM_F64, &n3);
  p->host = (const uint32_t *)rec_field(p->blk, "host", SHM_U32, &n4);
  p->port = (const int32_t *)rec_field(p->blk, "port", SHM_I32, &n5);
  p->data = (const uint8_t *)rec_field(p->blk, "data", SHM_U8, &bytes);
  if (!p->count || !p->source || !p->length || !p->time || !p->host || !p->port || !p->data || p->slots < 1 ||
      n2 != p->slots || n3 != p->slots || n4 != p->slots || n5 != p->slots || bytes % p->slots) {
    snprintf(err, errlen, "recorder: block '%s' (Config/shm.schema) needs u32 written and source, length, time, host, "
             "port of one count and u8 data of a multiple of it", REC_PACKETS_BLOCK);
    shm_block_close(p->blk);
    p->blk = NULL;
    return -EINVAL;
  }
  p->slot_bytes = (size_t)bytes / (size_t)p->slots;
  p->next = *p->count;   /* what was there before the recording started is not this recording's */
  return 0;
}

void rec_packets_close(rec_packets *p) {
  if (p->blk) shm_block_close(p->blk);
  p->blk = NULL;
}

static const char *source_name(int s) { return s == 1 ? "gamecontroller" : s == 2 ? "team" : "other"; }

/* Copies slot k (datagram number k) into a queued message; 0, 1 if the writer overwrote it meanwhile. */
static int take(rec_packets *p, uint32_t k, rec_queue *q, uint64_t log_time, uint64_t wall_ns) {
  uint8_t data[4096];
  const int s = (int)(k % (uint32_t)p->slots);
  for (int tries = 0; tries < 100; tries++) {
    uint32_t seq;
    if (shm_read_begin_checked(p->blk, &seq, NULL, 0) < 0) return 1;   /* the behavior died writing it */
    const uint32_t count = __atomic_load_n(p->count, __ATOMIC_ACQUIRE);
    const int source = p->source[s];
    int len = p->length[s];
    const double t = p->time[s];
    const uint32_t host = p->host[s];
    const int port = p->port[s];
    if (len < 0) len = 0;
    if ((size_t)len > p->slot_bytes) len = (int)p->slot_bytes;
    if ((size_t)len > sizeof data) len = (int)sizeof data;
    memcpy(data, p->data + (size_t)s * p->slot_bytes, (size_t)len);
    if (shm_read_retry(p->blk, seq)) continue;
    if (count - k > (uint32_t)p->slots) return 1;   /* overwritten before we got to it */
    char ip[16];
    snprintf(ip, sizeof ip, "%u.%u.%u.%u", host >> 24, (host >> 16) & 255, (host >> 8) & 255, host & 255);
    const size_t cap = (size_t)len + 128;
    rec_item *it = (rec_item *)malloc(sizeof *it + cap);
    if (!it) return 1;
    it->kind = REC_ITEM_PACKET;
    it->channel = source == 1 ? 0 : 1;
    it->log_time = log_time;
    it->publish_time = wall_ns;
    it->width = it->height = 0;
    it->len = shmlog_packet_encode(t, source_name(source), ip, (uint16_t)port, data, (size_t)len, it->data, cap);
    if (rec_queue_push(q, it) == 0) p->taken++;
    return 0;
  }
  return 1;
}

int rec_packets_sample(rec_packets *p, rec_queue *q, uint64_t log_time, uint64_t wall_ns) {
  if (!p->blk) return 0;
  const uint32_t count = __atomic_load_n(p->count, __ATOMIC_ACQUIRE);
  if (count - p->next > (uint32_t)p->slots) {   /* the ring went round since the last sample */
    p->lost += count - p->slots - p->next;
    p->next = count - (uint32_t)p->slots;
  }
  int queued = 0;
  for (; p->next != count; p->next++) {
    if (take(p, p->next, q, log_time, wall_ns)) p->lost++;
    else queued++;
  }
  return queued;
}
