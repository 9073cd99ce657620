/* mcap: a small writer and reader of MCAP files (https://mcap.dev/spec), the log format Foxglove,
 * PlotJuggler and the `mcap` tools read.
 *
 * Why our own: no package registry this project installs from (Debian 12, PyPI, npm, crates.io) serves
 * the C or C++ MCAP library, and the container is small: records of an opcode, a length and fields.
 * Tests/recorder checks the files with the reference `mcap` Python library.
 *
 * The writer puts Schema and Channel records before the messages, the messages in zstd-compressed
 * Chunks (with a ChunkIndex each in the summary), Attachments and Metadata between chunks, and a
 * summary (schemas, channels, statistics, chunk / attachment / metadata indexes, summary offsets) with
 * its CRC at close. A file cut short (the recorder killed) holds every chunk written before.
 *
 * The reader maps the file and walks its records in order (it needs no summary); it stops at the
 * first damage -- a record running past the end, a chunk that fails to decompress or whose CRC does
 * not match -- and says where, so a truncated log is read up to the damage.
 *
 * Errors: 0 / a count on success, a negative errno code on failure with a message. No exit().
 */
#ifndef HRP_MCAP_H
#define HRP_MCAP_H

#include <stddef.h>
#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

#define MCAP_NAME_MAX 128   /* schema names, topics, encodings kept by the reader */

/* CRC-32 (IEEE, as MCAP and zlib use), continued from crc (0 to start). */
uint32_t mcap_crc32(uint32_t crc, const void *data, size_t len);

/* ---------------------------------------------------------------- writer */

typedef struct mcap_writer mcap_writer;

/* Creates path. profile: the MCAP profile ("" for none); zstd_level: 0 = chunks uncompressed;
 * chunk_bytes: a chunk is closed once it holds this many bytes of records. */
int mcap_writer_open(const char *path, const char *profile, int zstd_level, size_t chunk_bytes,
                     mcap_writer **out, char *err, size_t errlen);
/* A schema; returns its id (1..) or a negative code. */
int mcap_writer_schema(mcap_writer *w, const char *name, const char *encoding, const void *data, size_t len);
/* A channel of schema_id (0: schemaless); meta: nmeta key/value pairs (may be NULL). Returns its id (0..). */
int mcap_writer_channel(mcap_writer *w, int schema_id, const char *topic, const char *message_encoding,
                        const char *const *meta, int nmeta);
/* One message (ns times). */
int mcap_writer_message(mcap_writer *w, int channel, uint32_t sequence, uint64_t log_time, uint64_t publish_time,
                        const void *data, size_t len);
/* An attachment (a file carried whole: the configuration in force). */
int mcap_writer_attachment(mcap_writer *w, const char *name, const char *media_type, uint64_t log_time,
                           const void *data, size_t len);
/* A metadata record: nmeta key/value pairs. */
int mcap_writer_metadata(mcap_writer *w, const char *name, const char *const *meta, int nmeta);
/* Writes the open chunk (a reader of the growing file sees everything so far). */
int mcap_writer_flush(mcap_writer *w);
/* Bytes in the file so far (the open chunk not counted). */
uint64_t mcap_writer_size(const mcap_writer *w);
/* Bytes of records in the open chunk (before compression). */
uint64_t mcap_writer_pending(const mcap_writer *w);
/* The last error's message. */
const char *mcap_writer_error(const mcap_writer *w);
/* Closes the last chunk, writes the summary and footer, closes the file and frees w. */
int mcap_writer_close(mcap_writer *w, char *err, size_t errlen);

/* ---------------------------------------------------------------- reader */

typedef struct mcap_reader mcap_reader;

typedef struct mcap_schema_info {
  int id;
  char name[MCAP_NAME_MAX];
  char encoding[MCAP_NAME_MAX];
  const uint8_t *data;     /* into the mapped file */
  size_t len;
} mcap_schema_info;

typedef struct mcap_channel_info {
  int id, schema_id;
  char topic[MCAP_NAME_MAX];
  char encoding[MCAP_NAME_MAX];
} mcap_channel_info;

typedef struct mcap_message {
  int channel;
  uint32_t sequence;
  uint64_t log_time, publish_time;   /* ns */
  const uint8_t *data;               /* valid until the next call */
  size_t len;
} mcap_message;

int mcap_reader_open(const char *path, mcap_reader **out, char *err, size_t errlen);
void mcap_reader_close(mcap_reader *r);
/* The next message: 1, 0 at the end of the data, or a negative code at damage (the message says
 * where: mcap_reader_error). Schema and channel records met on the way are kept. */
int mcap_reader_next(mcap_reader *r, mcap_message *m);
/* Back to the first record. */
void mcap_reader_rewind(mcap_reader *r);
/* Schemas / channels seen so far, by id (NULL if none). */
const mcap_schema_info *mcap_reader_schema(const mcap_reader *r, int id);
const mcap_channel_info *mcap_reader_channel(const mcap_reader *r, int id);
/* Reads every schema and channel record from the start up to the first message (or the end), then
 * rewinds; returns the number of channels. */
int mcap_reader_scan_channels(mcap_reader *r);
/* The first attachment named `name`: data and length, or NULL. */
const uint8_t *mcap_reader_attachment(mcap_reader *r, const char *name, size_t *len);
const char *mcap_reader_error(const mcap_reader *r);

#ifdef __cplusplus
}
#endif
#endif
