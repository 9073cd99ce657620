/* shmlog: a shm block as a logged message -- its ROS 2 message definition (ros2msg) generated from the
 * block's field table, and its CDR encoding -- for the recorder (Run/recorder) and the Replay DCM.
 *
 * Why ros2msg + CDR: a fixed layout of plain numbers is exactly what CDR (little endian, each value
 * aligned to its size) encodes, bit for bit, NaN and all, at the cost of a copy; and Foxglove,
 * PlotJuggler and the `mcap` Python library (mcap-ros2-support) decode it without ROS installed. The
 * definition is generated from the segment's field table, so a new field in Config/shm.schema needs
 * no code:
 *   block dcm.sensor: f64 position njoint   ->   hrp/msg/DcmSensor: "float64[32] position"
 *
 * A log made with another layout is found by comparing the recorded definition with the present one
 * (shmlog_diff names the first difference).
 */
#ifndef HRP_SHMLOG_H
#define HRP_SHMLOG_H

#include <stddef.h>
#include <stdint.h>

#include "shm/shm.h"

#ifdef __cplusplus
extern "C" {
#endif

#define SHMLOG_FIELDS_MAX 96
#define SHMLOG_DEF_MAX 8192

typedef struct shmlog_field {
  char name[SHM_NAME_MAX];
  int type;                 /* shm_type */
  int count;                /* elements */
  uint64_t shm_offset;      /* bytes from the segment start (0 for a parsed definition) */
  size_t cdr_offset;        /* bytes from the start of the CDR message (after its 4-byte header) */
} shmlog_field;

typedef struct shmlog_block {
  char name[SHM_NAME_MAX];  /* "dcm.sensor" */
  char type_name[128];      /* "hrp/msg/DcmSensor" */
  char topic[SHM_NAME_MAX + 2]; /* "/dcm.sensor" */
  int nfields;
  shmlog_field field[SHMLOG_FIELDS_MAX];
  size_t cdr_size;          /* bytes of an encoded message, header included */
  char def[SHMLOG_DEF_MAX]; /* the ros2msg text */
} shmlog_block;

/* The message of an open block, leaving out the fields named in skip (nskip names; e.g. the camera's
 * raw image when it is logged as JPEG). */
int shmlog_from_block(shm_block *b, const char *const *skip, int nskip, shmlog_block *out, char *err, size_t errlen);
/* The fields of a recorded definition (block name and ros2msg text). */
int shmlog_parse(const char *block, const char *def, size_t len, shmlog_block *out, char *err, size_t errlen);
/* 0 when the fields agree (name, type, count, order); else 1 and what differs, in words. */
int shmlog_diff(const shmlog_block *log, const shmlog_block *now, char *msg, size_t msglen);
/* ros2msg name of a shm type ("float64"), or NULL. */
const char *shmlog_type_name(int type);

/* Encodes the fields from a copy of the segment (seg: its first byte) into out (cdr_size bytes). */
void shmlog_encode(const shmlog_block *b, const uint8_t *seg, uint8_t *out);
/* Decodes a message into the segment copy or the segment itself; -EINVAL if the size is wrong. Every
   NaN in a float field is written as the one quiet NaN (a log is outside input). */
int shmlog_decode(const shmlog_block *b, const uint8_t *msg, size_t len, uint8_t *seg);

/* ---- the camera's compressed frame: sensor_msgs/msg/CompressedImage (what Foxglove shows) */
extern const char SHMLOG_IMAGE_TYPE[];   /* "sensor_msgs/msg/CompressedImage" */
extern const char SHMLOG_IMAGE_DEF[];    /* its definition with the nested types */
/* Encodes a frame (stamp in ns, format "jpeg") into out (capacity cap); returns its size or 0 if it
 * does not fit. */
size_t shmlog_image_encode(uint64_t stamp_ns, const char *frame_id, const char *format, const uint8_t *data,
                           size_t len, uint8_t *out, size_t cap);
/* Finds format and data in an encoded frame; 0, or -EINVAL when it is malformed. */
int shmlog_image_decode(const uint8_t *msg, size_t len, char *format, size_t formatlen, const uint8_t **data,
                        size_t *datalen);

/* ---- a UDP datagram as a process read it (packet.c): hrp/msg/Packet */
extern const char SHMLOG_PACKET_TYPE[];  /* "hrp/msg/Packet" */
extern const char SHMLOG_PACKET_DEF[];
/* Encodes one datagram into out (capacity cap); returns its size or 0 if it does not fit. */
size_t shmlog_packet_encode(double time, const char *source, const char *host, uint16_t port, const uint8_t *data,
                            size_t len, uint8_t *out, size_t cap);

#ifdef __cplusplus
}
#endif
#endif
