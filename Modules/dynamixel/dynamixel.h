/* dynamixel: ROBOTIS Dynamixel protocol 1.0 and 2.0 in C (libhrpdxl.so).
 *
 * Three layers, usable separately:
 *   packets     build and parse instruction/status packets (checksum, CRC-16, 2.0 byte stuffing);
 *               no I/O, no allocation: the part the fuzzer exercises.
 *   port        a serial port through termios: standard rates and custom ones up to 4.5 Mbps,
 *               low-latency mode, reads with deadlines, reopen after the adapter disappears.
 *   bus         instructions over a port with timeouts: ping, read, write, sync write, sync read
 *               (2.0), bulk read (1.0 and 2.0); every problem is counted in dxl_bus_stats.
 * Plus: libusb look-up of a USB adapter (U2D2, USB2Dynamixel, CM-730's FTDI) and its latency timer.
 *
 * Names follow the ROBOTIS SDK where one exists (COMM_* results, INST_*, ping/read/write,
 * sync write/read, bulk read, error bits) with our prefix.
 *
 * Errors: functions return 0 (or a length) on success and a negative DXL_COMM_* / DXL_E*
 * code on failure; those taking (err, errlen) write a message there. Nothing here calls exit().
 */
#ifndef HRP_DYNAMIXEL_H
#define HRP_DYNAMIXEL_H

#include <stddef.h>
#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

/* ---------------------------------------------------------------- constants */

#define DXL_BROADCAST_ID 0xFE
#define DXL_MAX_ID 0xFC           /* highest unicast id (252) */
#define DXL_MAX_PARAMS 1024       /* parameters kept in a parsed packet (longer packets: DXL_ETOOLONG) */
#define DXL_MAX_PACKET 2200       /* bytes of the largest packet we build (2.0, all stuffed) */

/* Instructions (same values in both protocols unless noted). */
enum {
  DXL_INST_PING = 0x01, DXL_INST_READ = 0x02, DXL_INST_WRITE = 0x03, DXL_INST_REG_WRITE = 0x04,
  DXL_INST_ACTION = 0x05, DXL_INST_FACTORY_RESET = 0x06, DXL_INST_REBOOT = 0x08 /* 2.0 */,
  DXL_INST_CLEAR = 0x10 /* 2.0 */, DXL_INST_STATUS = 0x55 /* 2.0 status packets */,
  DXL_INST_SYNC_READ = 0x82 /* 2.0 */, DXL_INST_SYNC_WRITE = 0x83, DXL_INST_BULK_READ = 0x92,
  DXL_INST_BULK_WRITE = 0x93 /* 2.0 */
};

/* Results (values of the ROBOTIS SDK's COMM_*), then our own. */
enum {
  DXL_COMM_SUCCESS = 0,
  DXL_COMM_PORT_BUSY = -1000,
  DXL_COMM_TX_FAIL = -1001,      /* write to the port failed */
  DXL_COMM_RX_FAIL = -1002,      /* read from the port failed */
  DXL_COMM_TX_ERROR = -2000,     /* bad instruction arguments (too long, bad id) */
  DXL_COMM_RX_WAITING = -3000,
  DXL_COMM_RX_TIMEOUT = -3001,   /* no (complete) answer before the deadline */
  DXL_COMM_RX_CORRUPT = -3002,   /* answer with a bad checksum/CRC or bad framing */
  DXL_COMM_NOT_AVAILABLE = -9000,/* instruction not in this protocol */
  DXL_EARG = -9100,              /* caller mistake: NULL pointer, bad protocol, buffer too small */
  DXL_ETRUNC = -9101,            /* packet truncated (more bytes needed) */
  DXL_ETOOLONG = -9102,          /* packet longer than DXL_MAX_PARAMS */
  DXL_EID = -9103,               /* answer from an id we did not ask */
  DXL_EORDER = -9104,            /* answer from an id already answered or out of turn */
  DXL_ESTATUS = -9105,           /* the servo answered with error bits set (see error) */
  DXL_EPORT = -9106              /* port missing / could not be opened */
};

/* Protocol 1.0 status error bits. */
enum {
  DXL1_ERR_VOLTAGE = 0x01, DXL1_ERR_ANGLE = 0x02, DXL1_ERR_OVERHEAT = 0x04, DXL1_ERR_RANGE = 0x08,
  DXL1_ERR_CHECKSUM = 0x10, DXL1_ERR_OVERLOAD = 0x20, DXL1_ERR_INSTRUCTION = 0x40
};
/* Protocol 2.0 status error: bit 7 = hardware alert, bits 0..6 = error number. */
enum {
  DXL2_ERR_ALERT = 0x80, DXL2_ERR_RESULT_FAIL = 1, DXL2_ERR_INSTRUCTION = 2, DXL2_ERR_CRC = 3,
  DXL2_ERR_DATA_RANGE = 4, DXL2_ERR_DATA_LENGTH = 5, DXL2_ERR_DATA_LIMIT = 6, DXL2_ERR_ACCESS = 7
};

/* Text of a result code (static string). */
const char *dxl_result_str(int result);
/* Text of a status error byte for a protocol ("overload|overheat", "ok"), into buf. */
const char *dxl_error_str(int protocol, uint8_t error, char *buf, size_t len);

/* ---------------------------------------------------------------- packets */

/* CRC-16 of protocol 2.0 (polynomial 0x8005, init 0, not reflected), continued from crc. */
uint16_t dxl_crc16(uint16_t crc, const uint8_t *data, size_t len);
/* Protocol 1.0 checksum: ~(sum of bytes) & 0xFF over id..last parameter. */
uint8_t dxl_checksum1(const uint8_t *data, size_t len);

/* 2.0 byte stuffing: after every FF FF FD in `in` insert an extra FD. Returns the stuffed length
 * or DXL_EARG if it does not fit in outlen. dxl_unstuff does the reverse (in place allowed). */
int dxl_stuff(const uint8_t *in, size_t len, uint8_t *out, size_t outlen);
int dxl_unstuff(const uint8_t *in, size_t len, uint8_t *out, size_t outlen);

/* Builds an instruction packet for `protocol` (1 or 2): header, id, length, instruction,
 * params (2.0: stuffed), checksum/CRC. Returns the packet length or a negative code. */
int dxl_build_instruction(int protocol, uint8_t id, uint8_t inst, const uint8_t *params,
                          size_t nparams, uint8_t *out, size_t outlen);
/* Builds a status packet (for the emulator and tests): error byte then params. */
int dxl_build_status(int protocol, uint8_t id, uint8_t error, const uint8_t *params,
                     size_t nparams, uint8_t *out, size_t outlen);

/* A parsed packet. For a status packet, `error` is the error byte and params follow it;
 * for an instruction packet, error is 0. */
typedef struct dxl_packet {
  int protocol;                  /* 1 or 2 */
  uint8_t id;
  uint8_t instruction;           /* 2.0: 0x55 for status; 1.0 status packets have none (0) */
  uint8_t error;
  uint16_t nparams;
  uint8_t params[DXL_MAX_PARAMS];/* 2.0: already unstuffed */
} dxl_packet;

/* Finds the next packet in buf[0..len). `is_status` selects how a 1.0 packet is read (the byte
 * after length is the error byte rather than an instruction; 2.0 tells by 0x55). A packet
 * declaring more than max_params parameters (0: DXL_MAX_PARAMS) is rejected as DXL_ETOOLONG
 * without waiting for its bytes (a corrupted length byte must not swallow what follows).
 * Returns:
 *   1   a valid packet: *pkt filled, *consumed = bytes up to its end;
 *   0   no complete packet yet: *consumed = leading bytes that can never start one (drop them),
 *       the rest must be kept and more bytes appended;
 *   <0  a bad packet (DXL_COMM_RX_CORRUPT bad checksum/CRC or framing, DXL_ETOOLONG):
 *       *consumed = bytes to drop to skip past it (at least 1).
 * Never reads outside buf[0..len). */
int dxl_parse(int protocol, int is_status, const uint8_t *buf, size_t len, size_t max_params,
              dxl_packet *pkt, size_t *consumed);

/* ---------------------------------------------------------------- serial port */

typedef struct dxl_port dxl_port;

/* Opens a serial port (8N1, raw, no flow control) at `baud` bits/s; rates without a Bxxx
 * constant (e.g. 4500000) are set with termios2/BOTHER. Tries low-latency mode (ignored
 * where the driver has none, e.g. a pseudo-terminal). */
int dxl_port_open(const char *path, int baud, dxl_port **out, char *err, size_t errlen);
void dxl_port_close(dxl_port *p);
/* Closes and opens again the same path (after the adapter was unplugged). */
int dxl_port_reopen(dxl_port *p, char *err, size_t errlen);
int dxl_port_set_baud(dxl_port *p, int baud, char *err, size_t errlen);
int dxl_port_baud(const dxl_port *p);
int dxl_port_fd(const dxl_port *p);
/* 1 if the port is open (0 after an I/O error that closed it). */
int dxl_port_is_open(const dxl_port *p);
/* Seconds per byte on the wire at the current rate (10 bits per byte). */
double dxl_port_byte_time(const dxl_port *p);
/* Writes all of buf. Returns len or DXL_COMM_TX_FAIL (then the port is marked closed). */
int dxl_port_write(dxl_port *p, const uint8_t *buf, size_t len);
/* Reads what is available, waiting at most until `deadline` (dxl_now() seconds) for the first
 * byte. Returns bytes read (0 at the deadline) or DXL_COMM_RX_FAIL. */
int dxl_port_read(dxl_port *p, uint8_t *buf, size_t len, double deadline);
/* Drops unread input. */
void dxl_port_clear(dxl_port *p);

/* Monotonic time in seconds. */
double dxl_now(void);

/* ---------------------------------------------------------------- USB adapters */

typedef struct dxl_usb_info {
  uint16_t vendor, product;
  uint8_t bus, address;
  char name[48];                 /* "U2D2", "USB2Dynamixel", "CM-730 (FTDI)" ... */
} dxl_usb_info;

/* Lists known Dynamixel adapters on the USB (libusb). Returns how many (up to max) or a negative
 * code; 0 with no device (or no USB at all) is not an error. */
int dxl_usb_find(dxl_usb_info *out, int max, char *err, size_t errlen);
/* Sets the FTDI latency timer of every found FTDI adapter to `ms` (1..255) through a USB
 * control transfer; falls back to /sys/bus/usb-serial/devices/<tty>/latency_timer for `tty`
 * (e.g. "ttyUSB0", may be NULL). Returns the number of adapters set (0: none found). */
int dxl_usb_set_latency(const char *tty, int ms, char *err, size_t errlen);

/* ---------------------------------------------------------------- bus (instructions) */

/* Counters of one bus; never reset by the library. */
typedef struct dxl_bus_stats {
  uint64_t tx_packets, tx_bytes;   /* instruction packets and bytes written */
  uint64_t rx_packets, rx_bytes;   /* valid status packets and all bytes read */
  uint64_t corrupt;                /* bad checksum/CRC or framing, skipped */
  uint64_t misaddressed;           /* valid packets from an id not asked */
  uint64_t out_of_order;           /* valid packets from an id answered already or out of turn */
  uint64_t timeouts;               /* expected answers that did not come */
  uint64_t status_errors;          /* answers with error bits set */
  uint64_t dropped_bytes;          /* garbage skipped while looking for a header */
  uint64_t port_errors;            /* I/O errors (port lost) */
} dxl_bus_stats;

typedef struct dxl_bus {
  dxl_port *port;                  /* not owned */
  int protocol;                    /* 1 or 2 */
  double timeout_margin;           /* s added to the wire time of an expected answer (USB latency,
                                      return delay); default 0.002 */
  dxl_bus_stats stats;
  double tx_until;                 /* dxl_now() when the bytes written so far have left the wire */
  uint8_t rx[4096];                /* receive buffer */
  size_t rxlen;
  uint8_t tx[DXL_MAX_PACKET];
  dxl_packet pkt;                  /* last parsed packet (scratch) */
} dxl_bus;

/* Prepares a bus on an open port for a protocol (1 or 2). */
int dxl_bus_init(dxl_bus *bus, dxl_port *port, int protocol);

/* Pings id; model number (and 2.0 firmware version) on success. */
int dxl_ping(dxl_bus *bus, uint8_t id, uint16_t *model, uint8_t *firmware, uint8_t *error);
/* Reads len bytes at addr of id into data. */
int dxl_read(dxl_bus *bus, uint8_t id, uint16_t addr, uint16_t len, uint8_t *data, uint8_t *error);
/* Writes len bytes at addr of id and waits for the status (no wait for broadcast). */
int dxl_write(dxl_bus *bus, uint8_t id, uint16_t addr, const uint8_t *data, uint16_t len,
              uint8_t *error);
/* Writes without waiting for a status (status return level 0/1, or broadcast). */
int dxl_write_nowait(dxl_bus *bus, uint8_t id, uint16_t addr, const uint8_t *data, uint16_t len);
/* Sync write: the same addr/len to n ids, data = n * len bytes in id order. No answer. */
int dxl_sync_write(dxl_bus *bus, uint16_t addr, uint16_t len, const uint8_t *ids, int n,
                   const uint8_t *data);

/* One item of a bulk read: read len bytes at addr of id into data (caller's storage). The
 * result of the item (0, DXL_COMM_RX_TIMEOUT, DXL_ESTATUS...) and error byte are filled in. */
typedef struct dxl_bulk_item {
  uint8_t id;
  uint16_t addr, len;
  uint8_t *data;
  int result;
  uint8_t error;
} dxl_bulk_item;

/* Sync read (2.0 only): the same addr/len from n ids; items[i].addr/len are ignored. */
int dxl_sync_read(dxl_bus *bus, uint16_t addr, uint16_t len, dxl_bulk_item *items, int n);
/* Bulk read (1.0 and 2.0): each item its own addr/len (1.0: len <= 255, addr <= 255). */
int dxl_bulk_read(dxl_bus *bus, dxl_bulk_item *items, int n);
/* Both return the number of items answered (0..n), or a negative code if nothing could be sent. */

/* Builds the parameters of sync write / sync read / bulk read (used by the bus and by tests).
 * Return the number of parameter bytes or a negative code. */
int dxl_sync_write_params(int protocol, uint16_t addr, uint16_t len, const uint8_t *ids, int n,
                          const uint8_t *data, uint8_t *out, size_t outlen);
int dxl_sync_read_params(uint16_t addr, uint16_t len, const uint8_t *ids, int n, uint8_t *out,
                         size_t outlen);
int dxl_bulk_read_params(int protocol, const dxl_bulk_item *items, int n, uint8_t *out,
                         size_t outlen);

/* Bytes on the wire of an instruction with nparams parameters / of a status with nparams data
 * bytes (without stuffing). */
int dxl_instruction_size(int protocol, int nparams);
int dxl_status_size(int protocol, int nparams);

/* Little-endian helpers. */
static inline uint16_t dxl_get16(const uint8_t *p) { return (uint16_t)(p[0] | (p[1] << 8)); }
static inline uint32_t dxl_get32(const uint8_t *p) {
  return (uint32_t)p[0] | ((uint32_t)p[1] << 8) | ((uint32_t)p[2] << 16) | ((uint32_t)p[3] << 24);
}
static inline void dxl_put16(uint8_t *p, uint16_t v) { p[0] = (uint8_t)v; p[1] = (uint8_t)(v >> 8); }
static inline void dxl_put32(uint8_t *p, uint32_t v) {
  p[0] = (uint8_t)v; p[1] = (uint8_t)(v >> 8); p[2] = (uint8_t)(v >> 16); p[3] = (uint8_t)(v >> 24);
}

#ifdef __cplusplus
}
#endif
#endif
