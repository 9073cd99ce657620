/* shm: self-describing POSIX shared-memory blocks shared by the DCM (C/C++) and the
 * robot's Lua processes (LuaJIT FFI).
 *
 * One POSIX shm object per block per robot, named "/hrp.<robot_id>.<block>".
 * Blocks and fields are declared once, in Config/shm.schema (see the README for the format).
 * Each segment starts with a header (magic, format version, layout hash) and a table of fields
 * (name, type, element count, byte offset), so any tool can find fields by name.
 *
 * Consistency: every block has a sequence lock. A writer brackets a multi-field update with
 * shm_write_begin / shm_write_end; a reader loops shm_read_begin / shm_read_retry. Readers
 * never block writers. Single aligned scalar writes need no lock.
 *
 * Errors: functions return 0 (or a pointer) on success and a negative code (or NULL) on
 * failure, with a message in the caller's buffer. Nothing here calls exit().
 */
#ifndef HRP_SHM_H
#define HRP_SHM_H

#include <stddef.h>
#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

/* ---------------------------------------------------------------- segment format */

#define SHM_MAGIC "HRPSHM\x01"   /* 8 bytes with the terminating NUL */
#define SHM_FORMAT_VERSION 1
#define SHM_NAME_MAX 48           /* field and block names, NUL included */

typedef enum shm_type {
  SHM_F64 = 1, SHM_F32 = 2, SHM_I32 = 3, SHM_U32 = 4,
  SHM_I64 = 5, SHM_U64 = 6, SHM_U8 = 7, SHM_I16 = 8, SHM_U16 = 9
} shm_type;

/* At offset 0 of every segment. 256 bytes; the field table follows at header_size. */
typedef struct shm_header {
  char magic[8];              /* SHM_MAGIC */
  uint32_t version;           /* SHM_FORMAT_VERSION */
  uint32_t header_size;       /* bytes, = sizeof(shm_header) */
  uint64_t layout_hash;       /* FNV-1a 64 of block name and (name,type,count) of every field */
  uint64_t total_size;        /* bytes of the whole segment */
  uint32_t nfields;           /* entries in the field table */
  uint32_t field_size;        /* bytes per field entry, = sizeof(shm_field) */
  uint32_t data_offset;       /* first byte of field data */
  uint32_t ready;             /* 0 while the creator initialises, 1 after */
  int32_t creator_pid;        /* process that created the segment */
  uint32_t waiters;           /* processes sleeping in shm_wait_write (skip the wake when 0) */
  uint64_t created_ns;        /* CLOCK_REALTIME at creation */
  char block[SHM_NAME_MAX];   /* block name, e.g. "dcm.sensor" */
  uint8_t pad0[64 - ((8 + 4 + 4 + 8 + 8 + 4 + 4 + 4 + 4 + 4 + 4 + 8 + SHM_NAME_MAX) % 64)];
  uint32_t seq;               /* sequence lock: odd while a writer is inside (own cache line) */
  uint32_t writes;            /* completed locked writes; futex word for shm_wait_write */
  int32_t writer_pid;         /* the process inside the sequence lock (0: none, or not yet known) */
  uint32_t writer_start;      /* its start time (/proc/PID/stat field 22, low 32 bits; 0: unknown): a
                                 live writer_pid with another start time is a reused pid */
  uint8_t pad1[256 - 128 - 16];
} shm_header;

/* One entry of the field table. 64 bytes. */
typedef struct shm_field {
  char name[SHM_NAME_MAX];
  uint32_t type;              /* shm_type */
  uint32_t count;             /* elements */
  uint64_t offset;            /* bytes from the segment start, aligned to 8 */
} shm_field;

/* ---------------------------------------------------------------- schema */

typedef struct shm_schema shm_schema;   /* all blocks of Config/shm.schema */

/* Loads a schema file (NULL: $HRP_SCHEMA, else <root>/Config/shm.schema where root is
 * $HRP_ROOT or the build tree). Constants may be overridden by
 * <root>/Config/$PLATFORM/shm.consts. */
int shm_schema_load(const char *path, shm_schema **out, char *err, size_t errlen);
void shm_schema_free(shm_schema *schema);
/* Number of blocks and the name of block i (0-based), for tools. */
int shm_schema_nblocks(const shm_schema *schema);
const char *shm_schema_block_name(const shm_schema *schema, int i);
/* Fields of block i (0-based): their number (-1 if no such block), and entry k with name, type
 * and count (and the offset a segment of it has), for generators such as Modules/dcm's. */
int shm_schema_block_nfields(const shm_schema *schema, int i);
const shm_field *shm_schema_block_field(const shm_schema *schema, int i, int k);
/* Value of a schema constant (e.g. "njoint"), or -1 if absent. */
long shm_schema_const(const shm_schema *schema, const char *name);

/* ---------------------------------------------------------------- blocks */

typedef struct shm_block shm_block;

enum {
  SHM_OPEN_CREATE = 1,     /* create the segment if it does not exist (the usual case) */
  SHM_OPEN_NOSCHEMA = 2    /* attach to an existing segment as it describes itself (tools) */
};

/* Robot id from $ROBOT_ID (default 1). */
int shm_robot_id(void);
/* Segment name "/hrp.<robot>.<block>" into buf. */
void shm_segment_name(int robot_id, const char *block, char *buf, size_t len);

/* Opens block `block` of robot `robot_id` as declared in `schema` (NULL: load the default
 * schema). Creates it with SHM_OPEN_CREATE. An existing segment whose layout differs from
 * the schema is an error naming the block and the difference, unless its creator is dead
 * (a stale segment from a crashed run), in which case it is removed and recreated. */
int shm_block_open(const shm_schema *schema, const char *block, int robot_id, int flags,
                   shm_block **out, char *err, size_t errlen);
void shm_block_close(shm_block *b);
/* Removes the segment name (existing mappings stay valid). 0, or -ENOENT if absent. */
int shm_block_unlink(const char *block, int robot_id);
/* 1 if the block's name now leads to another segment or none (removed, or recreated with another
 * layout, while this one stayed mapped): reopen it to see what others see. 0 same, <0 -errno. */
int shm_block_replaced(const shm_block *b);

shm_header *shm_block_header(shm_block *b);
const char *shm_block_name(const shm_block *b);
/* Field table entry i (0-based) or NULL; number of fields. */
const shm_field *shm_block_field(const shm_block *b, int i);
int shm_block_nfields(const shm_block *b);
/* Address of a field's first element, or NULL if the block has no such field. Looks the name
 * up linearly: call once at start and keep the pointer. type/count may be NULL. */
void *shm_field_ptr(shm_block *b, const char *field, int *type, int *count);
/* Like shm_field_ptr but requires the type and at least min_count elements; NULL and a
 * message naming block and field otherwise. */
void *shm_field_require(shm_block *b, const char *field, int type, int min_count,
                        char *err, size_t errlen);

/* Sequence lock. Writers may be several processes: begin spins (with yields) while another
 * writer is inside, and takes over after ~10 ms from a writer that died mid-update. */
void shm_write_begin(shm_block *b);
void shm_write_end(shm_block *b);
uint32_t shm_read_begin(const shm_block *b);   /* waits while a write is in progress */
int shm_read_retry(const shm_block *b, uint32_t seq);  /* 1: the read was torn, read again */
/* Like shm_read_begin, but a writer that died mid-update (the sequence odd for SHM_STALE_S while its
 * writer_pid is no process, a zombie, or a pid reused by another process) does not hold the reader:
 * -EOWNERDEAD and a message naming the block and the pid ("block 'dcm.sensor' is stale: its writer
 * (pid 1234) died mid-update"); nor does one stopped mid-update (SIGSTOP, a debugger: it may never
 * be continued): -EAGAIN ("... its writer (pid 1234) is stopped mid-update"). A running writer is
 * waited for however long it takes. 0 and *seq otherwise. shm_read_begin itself returns the odd
 * sequence then (the read is of a half-written block; it says so once on stderr) rather than spinning
 * for ever; the next writer takes the lock over and the block is whole again. */
#define SHM_STALE_S 0.02
int shm_read_begin_checked(const shm_block *b, uint32_t *seq, char *err, size_t errlen);

/* Blocks until the block's completed-write counter differs from `last` or timeout_s passes
 * (futex on the segment). Returns the current counter. */
uint32_t shm_wait_write(shm_block *b, uint32_t last, double timeout_s);

/* Futex helpers on a 32-bit word inside any block (for lockstep): wait while *addr == val. */
int shm_futex_wait(volatile uint32_t *addr, uint32_t val, double timeout_s);
int shm_futex_wake(volatile uint32_t *addr);
/* Atomic helpers for LuaJIT, which has no atomics of its own. */
int shm_cas_i32(volatile int32_t *addr, int32_t expected, int32_t desired);
uint32_t shm_fetch_add_u32(volatile uint32_t *addr, uint32_t delta);
void shm_store_release_u32(volatile uint32_t *addr, uint32_t val);
uint32_t shm_load_acquire_u32(const volatile uint32_t *addr);

/* Monotonic wall time in seconds (benchmarks, pacing; robot code uses the DCM clock). */
double shm_now(void);
/* 1 if a process with this pid exists. */
int shm_pid_alive(int pid);
/* Its state letter in /proc/PID/stat ('R', 'S', 'T' stopped, 't' stopped by a tracer, 'Z' ...), or
 * 0 when there is no such process; *start (may be NULL) gets its start time (field 22, clock ticks
 * after boot), which tells a reused pid. */
int shm_pid_state(int pid, unsigned long long *start);
/* 1 if the process is stopped (SIGSTOP, or by a tracer): it does nothing until continued. */
int shm_pid_stopped(int pid);

#ifdef __cplusplus
}
#endif
#endif
