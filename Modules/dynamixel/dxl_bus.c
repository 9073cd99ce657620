/* dxl_bus.c: Dynamixel instructions over a port with timeouts: ping, read, write, sync write,
 * sync read (2.0), bulk read (1.0 / 2.0). Answers are matched to the ids asked; corrupt,
 * misaddressed and out-of-order packets are counted and skipped; a missing answer costs at
 * most the bus deadline and never blocks the answers after it. */
#include "dynamixel/dynamixel.h"

#include <string.h>

int dxl_bus_init(dxl_bus *bus, dxl_port *port, int protocol) {
  if (!bus || (protocol != 1 && protocol != 2)) return DXL_EARG;
  memset(bus, 0, sizeof *bus);
  bus->port = port;
  bus->protocol = protocol;
  bus->timeout_margin = 0.002;
  return 0;
}

/* Sends one instruction, dropping stale input first. */
static int send(dxl_bus *bus, uint8_t id, uint8_t inst, const uint8_t *params, size_t n) {
  if (!bus->port || !dxl_port_is_open(bus->port)) { bus->stats.port_errors++; return DXL_EPORT; }
  int len = dxl_build_instruction(bus->protocol, id, inst, params, n, bus->tx, sizeof bus->tx);
  if (len < 0) return len == DXL_EARG ? DXL_COMM_TX_ERROR : len;
  dxl_port_clear(bus->port);
  bus->rxlen = 0;
  int w = dxl_port_write(bus->port, bus->tx, (size_t)len);
  if (w != len) { bus->stats.port_errors++; return DXL_COMM_TX_FAIL; }
  bus->stats.tx_packets++;
  bus->stats.tx_bytes += (uint64_t)len;
  /* write() returns while the UART still sends: the bus is busy until the bytes are out */
  double now = dxl_now(), bt = dxl_port_byte_time(bus->port);
  bus->tx_until = (bus->tx_until > now ? bus->tx_until : now) + len * bt;
  return len;
}

static void drop(dxl_bus *bus, size_t n) {
  if (n > bus->rxlen) n = bus->rxlen;
  memmove(bus->rx, bus->rx + n, bus->rxlen - n);
  bus->rxlen -= n;
}

/* Receives the answers to items[0..n) (each with items[k].len data bytes, in order) until all
 * came or `deadline`. Fills result/error/data of every item. Returns answers received or
 * DXL_COMM_RX_FAIL if the port failed. */
static int receive(dxl_bus *bus, dxl_bulk_item *items, int n, double deadline) {
  size_t maxp = 0;
  for (int k = 0; k < n; k++) {
    items[k].result = DXL_COMM_RX_TIMEOUT;
    items[k].error = 0;
    if (items[k].len > maxp) maxp = items[k].len;
  }
  if (bus->protocol == 2) maxp += 3;   /* ping answers carry 3 bytes with len 0 asked */
  if (maxp == 0) maxp = 1;
  /* bytes of all the answers: once that many came and nothing parses, the rest was corrupt or
   * lost and waiting on is pointless (2.0 stuffing can add bytes: then we wait as usual) */
  size_t expect = 0, received = 0;
  for (int k = 0; k < n; k++) expect += (size_t)dxl_status_size(bus->protocol, items[k].len);
  int next = 0, answered = 0, rc = 0;
  uint64_t corrupt0 = bus->stats.corrupt;
  dxl_packet *pkt = &bus->pkt;
  while (next < n) {
    size_t used = 0;
    int r = dxl_parse(bus->protocol, 1, bus->rx, bus->rxlen, maxp, pkt, &used);
    if (r == 1) {
      drop(bus, used);
      if (bus->protocol == 2 && pkt->instruction != DXL_INST_STATUS) continue;   /* an echo */
      int k = -1;
      for (int j = next; j < n; j++) if (items[j].id == pkt->id) { k = j; break; }
      if (k < 0) {
        int seen = 0;
        for (int j = 0; j < next; j++) if (items[j].id == pkt->id) seen = 1;
        if (seen) bus->stats.out_of_order++;
        else bus->stats.misaddressed++;
        continue;
      }
      size_t want = items[k].len;
      if (pkt->nparams != want && !(items[k].len == 0 && bus->protocol == 2)) {
        bus->stats.corrupt++;   /* valid frame, wrong size for what was asked */
        continue;
      }
      for (int j = next; j < k; j++) bus->stats.timeouts++;   /* bus order: those will not come */
      if (items[k].data && want) memcpy(items[k].data, pkt->params, want);
      items[k].error = pkt->error;
      items[k].result = DXL_COMM_SUCCESS;
      if (pkt->error) bus->stats.status_errors++;
      bus->stats.rx_packets++;
      answered++;
      next = k + 1;
      continue;
    }
    if (r < 0) {
      bus->stats.corrupt++;
      drop(bus, used ? used : 1);
      continue;
    }
    if (used) { bus->stats.dropped_bytes += used; drop(bus, used); }
    if (received >= expect && bus->stats.corrupt > corrupt0) break;
    if (bus->rxlen >= sizeof bus->rx) { bus->stats.corrupt++; drop(bus, 1); continue; }
    int got = dxl_port_read(bus->port, bus->rx + bus->rxlen, sizeof bus->rx - bus->rxlen, deadline);
    if (got < 0) { bus->stats.port_errors++; rc = DXL_COMM_RX_FAIL; break; }
    if (got == 0) break;   /* deadline */
    bus->rxlen += (size_t)got;
    received += (size_t)got;
    bus->stats.rx_bytes += (uint64_t)got;
  }
  for (int j = next; j < n; j++) bus->stats.timeouts++;
  return rc ? rc : answered;
}

/* Deadline for answers of `rxbytes` after the request of `txbytes` (already counted in
 * tx_until, with whatever was still queued before it) has left. */
static double deadline_for(dxl_bus *bus, int txbytes, int rxbytes) {
  double bt = dxl_port_byte_time(bus->port), now = dxl_now();
  double start = bus->tx_until > now ? bus->tx_until : now;
  return start + (0.25 * txbytes + 1.25 * rxbytes) * bt + bus->timeout_margin;
}

static int single(dxl_bus *bus, uint8_t id, uint8_t inst, const uint8_t *params, size_t np,
                  uint16_t want, uint8_t *data, uint8_t *error) {
  if (error) *error = 0;
  if (id == DXL_BROADCAST_ID || id > DXL_MAX_ID) return DXL_COMM_TX_ERROR;
  int len = send(bus, id, inst, params, np);
  if (len < 0) return len;
  dxl_bulk_item it = { id, 0, want, data, 0, 0 };
  int r = receive(bus, &it, 1, deadline_for(bus, len, dxl_status_size(bus->protocol, want + 3)));
  if (r < 0) return r;
  if (error) *error = it.error;
  return it.result;
}

int dxl_ping(dxl_bus *bus, uint8_t id, uint16_t *model, uint8_t *firmware, uint8_t *error) {
  if (!bus) return DXL_EARG;
  if (bus->protocol == 1) {
    int r = single(bus, id, DXL_INST_PING, NULL, 0, 0, NULL, error);
    if (r || !model) return r;
    uint8_t d[2];
    r = dxl_read(bus, id, 0, 2, d, error);
    if (r == 0) *model = dxl_get16(d);
    if (firmware) *firmware = 0;
    return r;
  }
  /* 2.0: the answer carries model number and firmware version; item len 0 accepts it */
  if (id == DXL_BROADCAST_ID || id > DXL_MAX_ID) return DXL_COMM_TX_ERROR;
  if (error) *error = 0;
  int len = send(bus, id, DXL_INST_PING, NULL, 0);
  if (len < 0) return len;
  dxl_bulk_item it = { id, 0, 0, NULL, 0, 0 };
  int r = receive(bus, &it, 1, deadline_for(bus, len, dxl_status_size(2, 3)));
  if (r < 0) return r;
  if (error) *error = it.error;
  if (it.result) return it.result;
  if (bus->pkt.nparams < 3) return DXL_COMM_RX_CORRUPT;
  if (model) *model = dxl_get16(bus->pkt.params);
  if (firmware) *firmware = bus->pkt.params[2];
  return 0;
}

int dxl_read(dxl_bus *bus, uint8_t id, uint16_t addr, uint16_t len, uint8_t *data, uint8_t *error) {
  if (!bus || !data || len == 0) return DXL_EARG;
  uint8_t p[4];
  size_t np;
  if (bus->protocol == 1) {
    if (addr > 255 || len > 255) return DXL_COMM_TX_ERROR;
    p[0] = (uint8_t)addr; p[1] = (uint8_t)len; np = 2;
  } else {
    dxl_put16(p, addr); dxl_put16(p + 2, len); np = 4;
  }
  if (len > DXL_MAX_PARAMS) return DXL_COMM_TX_ERROR;
  return single(bus, id, DXL_INST_READ, p, np, len, data, error);
}

static int write_params(dxl_bus *bus, uint16_t addr, const uint8_t *data, uint16_t len,
                        uint8_t *p, size_t cap) {
  size_t hdr = bus->protocol == 1 ? 1 : 2;
  if ((!data && len) || hdr + len > cap) return DXL_COMM_TX_ERROR;
  if (bus->protocol == 1) { if (addr > 255) return DXL_COMM_TX_ERROR; p[0] = (uint8_t)addr; }
  else dxl_put16(p, addr);
  memcpy(p + hdr, data, len);
  return (int)(hdr + len);
}

int dxl_write(dxl_bus *bus, uint8_t id, uint16_t addr, const uint8_t *data, uint16_t len,
              uint8_t *error) {
  if (!bus) return DXL_EARG;
  if (id == DXL_BROADCAST_ID) return dxl_write_nowait(bus, id, addr, data, len);
  uint8_t p[DXL_MAX_PARAMS + 2];
  int np = write_params(bus, addr, data, len, p, sizeof p);
  if (np < 0) return np;
  return single(bus, id, DXL_INST_WRITE, p, (size_t)np, 0, NULL, error);
}

int dxl_write_nowait(dxl_bus *bus, uint8_t id, uint16_t addr, const uint8_t *data, uint16_t len) {
  if (!bus) return DXL_EARG;
  uint8_t p[DXL_MAX_PARAMS + 2];
  int np = write_params(bus, addr, data, len, p, sizeof p);
  if (np < 0) return np;
  int r = send(bus, id, DXL_INST_WRITE, p, (size_t)np);
  return r < 0 ? r : 0;
}

int dxl_sync_write(dxl_bus *bus, uint16_t addr, uint16_t len, const uint8_t *ids, int n,
                   const uint8_t *data) {
  if (!bus) return DXL_EARG;
  uint8_t p[DXL_MAX_PACKET];
  int np = dxl_sync_write_params(bus->protocol, addr, len, ids, n, data, p, sizeof p - 16);
  if (np < 0) return np == DXL_EARG ? DXL_COMM_TX_ERROR : np;
  int r = send(bus, DXL_BROADCAST_ID, DXL_INST_SYNC_WRITE, p, (size_t)np);
  return r < 0 ? r : 0;
}

int dxl_sync_read(dxl_bus *bus, uint16_t addr, uint16_t len, dxl_bulk_item *items, int n) {
  if (!bus || !items || n <= 0 || n > 253 || len == 0) return DXL_EARG;
  if (bus->protocol != 2) return DXL_COMM_NOT_AVAILABLE;
  uint8_t ids[256], p[260];
  for (int k = 0; k < n; k++) { ids[k] = items[k].id; items[k].addr = addr; items[k].len = len; }
  int np = dxl_sync_read_params(addr, len, ids, n, p, sizeof p);
  if (np < 0) return np;
  int sent = send(bus, DXL_BROADCAST_ID, DXL_INST_SYNC_READ, p, (size_t)np);
  if (sent < 0) return sent;
  int rx = n * dxl_status_size(2, len);
  return receive(bus, items, n, deadline_for(bus, sent, rx));
}

int dxl_bulk_read(dxl_bus *bus, dxl_bulk_item *items, int n) {
  if (!bus || !items || n <= 0 || n > 253) return DXL_EARG;
  uint8_t p[5 * 256];
  int np = dxl_bulk_read_params(bus->protocol, items, n, p, sizeof p);
  if (np < 0) return np;
  int sent = send(bus, DXL_BROADCAST_ID, DXL_INST_BULK_READ, p, (size_t)np);
  if (sent < 0) return sent;
  int rx = 0;
  for (int k = 0; k < n; k++) rx += dxl_status_size(bus->protocol, items[k].len);
  return receive(bus, items, n, deadline_for(bus, sent, rx));
}
