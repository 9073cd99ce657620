/* Unit tests of the shm module (TAP). Uses ROBOT_ID from the environment (test runner). */
#include "shm/shm.h"
#include "tap.h"

#include <errno.h>
#include <signal.h>
#include <sched.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <fcntl.h>
#include <sys/mman.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>


static void shm_sleep_s(double s) {
  struct timespec ts = { (time_t)s, (long)((s - (double)(time_t)s) * 1e9) };
  nanosleep(&ts, NULL);
}

static char dir[256];
static const char *write_file(const char *name, const char *text) {
  static char path[512];
  snprintf(path, sizeof path, "%s/%s", dir, name);
  FILE *f = fopen(path, "w");
  fputs(text, f);
  fclose(f);
  return path;
}

static const char *SCHEMA_A =
  "const n 4\n"
  "block t.a   # comment\n"
  "  f64 x n\n  u32 tick 1\n  u8 bytes 3\n  f64 y 1\n";
static const char *SCHEMA_B =   /* same block, one field grown */
  "const n 5\nblock t.a\n  f64 x n\n  u32 tick 1\n  u8 bytes 3\n  f64 y 1\n";

static int robot;

static void test_schema_errors(void) {
  char err[512];
  shm_schema *s = NULL;
  int rc = shm_schema_load(write_file("bad1.schema", "block t.b\n  f99 x 1\n"), &s, err, sizeof err);
  check(rc < 0 && strstr(err, "bad1.schema:2"), "unknown type is an error naming file and line");
  rc = shm_schema_load(write_file("bad2.schema", "block t.b\n  f64 x nope\n"), &s, err, sizeof err);
  check(rc < 0 && strstr(err, "unknown constant 'nope'"), "unknown constant is named");
  rc = shm_schema_load(write_file("bad3.schema", "f64 x 1\n"), &s, err, sizeof err);
  check(rc < 0 && strstr(err, "outside a block"), "field outside a block is an error");
  rc = shm_schema_load("/nonexistent/x.schema", &s, err, sizeof err);
  check(rc < 0 && strstr(err, "/nonexistent/x.schema"), "missing schema file is named");
}

/* Loads SCHEMA_A into *s and creates block t.a afresh (one left by an earlier run is unlinked first).
 * Returns shm_block_open's code. */
static int create_a(shm_schema **s, shm_block **b, char *err, size_t errlen) {
  shm_schema_load(write_file("a.schema", SCHEMA_A), s, err, errlen);
  shm_block_unlink("t.a", robot);
  return shm_block_open(*s, "t.a", robot, SHM_OPEN_CREATE, b, err, errlen);
}

static void test_create_attach(void) {
  char err[512];
  shm_schema *s = NULL;
  int rc = shm_schema_load(write_file("a.schema", SCHEMA_A), &s, err, sizeof err);
  check(rc == 0, "schema loads");
  check(shm_schema_const(s, "n") == 4, "constant is read");
  shm_block_unlink("t.a", robot);
  shm_block *w = NULL, *r = NULL;
  rc = shm_block_open(s, "t.a", robot, SHM_OPEN_CREATE, &w, err, sizeof err);
  check(rc == 0, "block is created");
  rc = shm_block_open(s, "t.a", robot, 0, &r, err, sizeof err);
  check(rc == 0, "second handle attaches");
  int type = 0, count = 0;
  double *x = shm_field_ptr(w, "x", &type, &count);
  check(x && type == SHM_F64 && count == 4, "field x found with type and count");
  check(((uintptr_t)x % 8) == 0, "fields are 8-byte aligned");
  double *rx = shm_field_ptr(r, "x", NULL, NULL);
  x[3] = 42.5;
  check(rx[3] == 42.5, "write through one mapping is seen through the other");
  check(shm_field_ptr(w, "nope", NULL, NULL) == NULL, "absent field gives NULL");
  void *p = shm_field_require(w, "tick", SHM_F64, 1, err, sizeof err);
  check(!p && strstr(err, "'t.a'") && strstr(err, "'tick'"), "wrong field type is named");
  shm_header *h = shm_block_header(w);
  check(memcmp(h->magic, SHM_MAGIC, 8) == 0 && h->version == SHM_FORMAT_VERSION && h->nfields == 4,
        "header is self-describing");
  shm_block *other = NULL;
  rc = shm_block_open(s, "t.nope", robot, SHM_OPEN_CREATE, &other, err, sizeof err);
  check(rc < 0 && strstr(err, "t.nope"), "unknown block is named");
  /* a field table broken by somebody else: the tools' open (no schema) refuses it, naming the field
   * (found by Tests/foundation/shm_fuzz_test.sh: a field's offset pointed outside the mapping) */
  shm_field *table = (shm_field *)((uint8_t *)h + sizeof(shm_header));
  const uint64_t good = table[1].offset;
  table[1].offset = (uint64_t)1 << 40;
  rc = shm_block_open(NULL, "t.a", robot, SHM_OPEN_NOSCHEMA, &other, err, sizeof err);
  check(rc < 0 && strstr(err, "field 1") && strstr(err, "outside the segment"),
        "a field outside the segment is refused (no schema), the field named");
  table[1].offset = good;
  table[2].type = 77;
  rc = shm_block_open(NULL, "t.a", robot, SHM_OPEN_NOSCHEMA, &other, err, sizeof err);
  check(rc < 0 && strstr(err, "unknown type"), "a field of an unknown type is refused (no schema)");
  table[2].type = SHM_F64;
  rc = shm_block_open(NULL, "t.a", robot, SHM_OPEN_NOSCHEMA, &other, err, sizeof err);
  check(rc == 0, "the repaired segment opens as it describes itself");
  if (rc == 0) shm_block_close(other);
  shm_block_close(r);
  shm_block_close(w);
  shm_schema_free(s);
}

/* A block removed or recreated while a process keeps its mapping: the process can tell, so
 * no process misreads a recreated segment. */
static void test_replaced(void) {
  char err[512];
  shm_schema *s = NULL;
  shm_block *w = NULL, *r = NULL, *again = NULL;
  int rc = create_a(&s, &w, err, sizeof err);
  rc |= shm_block_open(s, "t.a", robot, 0, &r, err, sizeof err);
  check(rc == 0 && shm_block_replaced(w) == 0 && shm_block_replaced(r) == 0,
        "creator and attacher: the name leads to their segment");
  shm_block_unlink("t.a", robot);
  check(shm_block_replaced(r) == 1, "a removed block is seen as replaced by who still maps it");
  rc = shm_block_open(s, "t.a", robot, SHM_OPEN_CREATE, &again, err, sizeof err);
  check(rc == 0 && shm_block_replaced(r) == 1 && shm_block_replaced(w) == 1 && shm_block_replaced(again) == 0,
        "a recreated block: the old mappings are replaced, the new one is not");
  if (again) shm_block_close(again);
  shm_block_close(r);
  shm_block_close(w);
  shm_schema_free(s);
}

static void test_layout_mismatch(void) {
  char err[512];
  shm_schema *a = NULL, *b = NULL;
  shm_schema_load(write_file("a.schema", SCHEMA_A), &a, err, sizeof err);
  shm_schema_load(write_file("b.schema", SCHEMA_B), &b, err, sizeof err);
  shm_block_unlink("t.a", robot);
  shm_block *w = NULL, *r = NULL;
  shm_block_open(a, "t.a", robot, SHM_OPEN_CREATE, &w, err, sizeof err);
  /* Creator (this process) alive: a different layout is an error naming block and difference. */
  int rc = shm_block_open(b, "t.a", robot, SHM_OPEN_CREATE, &r, err, sizeof err);
  check(rc < 0 && strstr(err, "'t.a'") && strstr(err, "field 'x' is f64[4] in the segment but f64[5]"),
        "layout mismatch fails naming block and difference");
  shm_block_close(w);
  shm_block_unlink("t.a", robot);

  /* Creator dead: the segment is stale and gets recreated with the new layout. */
  pid_t pid = fork();
  if (pid == 0) {
    shm_block *c = NULL;
    char e2[256];
    _exit(shm_block_open(a, "t.a", robot, SHM_OPEN_CREATE, &c, e2, sizeof e2) == 0 ? 0 : 1);
  }
  int status = 0;
  waitpid(pid, &status, 0);
  rc = shm_block_open(b, "t.a", robot, SHM_OPEN_CREATE, &r, err, sizeof err);
  int cnt = 0;
  check(rc == 0 && shm_field_ptr(r, "x", NULL, &cnt) && cnt == 5,
        "stale segment of a dead creator with an old layout is recreated");
  if (rc == 0) shm_block_close(r);

  /* Garbage in the segment (crash before the header was written): recreated, not misread. */
  shm_block_unlink("t.a", robot);
  char name[128];
  shm_segment_name(robot, "t.a", name, sizeof name);
  int fd = shm_open(name, O_RDWR | O_CREAT, 0600);
  check(ftruncate(fd, 4096) == 0, "garbage segment made");
  close(fd);
  rc = shm_block_open(a, "t.a", robot, SHM_OPEN_CREATE, &r, err, sizeof err);
  check(rc == 0 && memcmp(shm_block_header(r)->magic, SHM_MAGIC, 8) == 0,
        "segment without a valid header is recreated");
  if (rc == 0) shm_block_close(r);
  shm_block_unlink("t.a", robot);
  rc = shm_block_open(a, "t.a", robot, 0, &r, err, sizeof err);
  check(rc == -ENOENT && strstr(err, "does not exist"), "attach without create to a missing block fails");
  shm_schema_free(a);
  shm_schema_free(b);
}

/* A writer process keeps x[0..3] = {k, 2k, 3k, 4k} under the seqlock; readers must never see a mix. */
static void test_seqlock_consistency(void) {
  char err[512];
  shm_schema *s = NULL;
  shm_block *b = NULL;
  create_a(&s, &b, err, sizeof err);
  volatile double *x = shm_field_ptr(b, "x", NULL, NULL);
  pid_t writers[2];
  for (int wi = 0; wi < 2; wi++) {
    writers[wi] = fork();
    if (writers[wi] == 0) {
      shm_block *wb = NULL;
      char e2[256];
      if (shm_block_open(s, "t.a", robot, 0, &wb, e2, sizeof e2) < 0) _exit(2);
      volatile double *wx = shm_field_ptr(wb, "x", NULL, NULL);
      for (long k = 1; k <= 300000; k++) {
        shm_write_begin(wb);
        double v = (double)(k * 2 + wi);
        for (int i = 0; i < 4; i++) wx[i] = v * (i + 1);
        shm_write_end(wb);
        /* a pause now and then, as every real writer has (the DCM writes at 125 Hz): two writers
         * back to back leave a reader no even sequence to start from on a loaded machine */
        if (k % 1024 == 0) sched_yield();
      }
      _exit(0);
    }
  }
  long reads = 0, torn = 0, retries = 0;
  int alive = 2;
  while (alive > 0) {
    double v[4];
    uint32_t q;
    do {
      q = shm_read_begin(b);
      for (int i = 0; i < 4; i++) v[i] = x[i];
      retries++;
    } while (shm_read_retry(b, q));
    retries--;
    reads++;
    for (int i = 1; i < 4; i++)
      if (v[i] != v[0] * (i + 1)) torn++;
    int st;
    while (alive > 0 && waitpid(-1, &st, WNOHANG) > 0) alive--;
  }
  printf("# seqlock: %ld consistent reads, %ld retries, %ld torn\n", reads, retries, torn);
  check(torn == 0 && reads > 1000, "multi-field updates by two writer processes are seen whole");
  check(shm_block_header(b)->writes == 600000, "every locked write was counted");
  shm_block_close(b);
  shm_block_unlink("t.a", robot);
  shm_schema_free(s);
}

/* A writer that dies inside its update must not wedge other writers. */
static void test_dead_writer(void) {
  char err[512];
  shm_schema *s = NULL;
  shm_block *b = NULL;
  create_a(&s, &b, err, sizeof err);
  pid_t pid = fork();
  if (pid == 0) {
    shm_block *wb = NULL;
    char e2[256];
    shm_block_open(s, "t.a", robot, 0, &wb, e2, sizeof e2);
    shm_write_begin(wb);
    _exit(0);   /* dies mid-update */
  }
  /* readers: not spinning for ever on it, first while it is an unreaped zombie, then gone */
  while (!(shm_block_header(b)->seq & 1u)) shm_sleep_s(0.001);
  shm_sleep_s(0.05);   /* dead by now (it only had _exit left to do) */
  uint32_t q = 0;
  char why[200] = "";
  double t0 = shm_now();
  int rc = shm_read_begin_checked(b, &q, why, sizeof why);
  char pidname[32];
  snprintf(pidname, sizeof pidname, "pid %d", (int)pid);
  printf("# %s (%.0f ms)\n", why, 1e3 * (shm_now() - t0));
  check(rc == -EOWNERDEAD && strstr(why, "'t.a'") && strstr(why, pidname) && shm_now() - t0 < 1.0,
        "a reader of a block whose writer died mid-update (a zombie yet) returns: stale, block and pid named");
  waitpid(pid, NULL, 0);
  t0 = shm_now();
  rc = shm_read_begin_checked(b, &q, why, sizeof why);
  check(rc == -EOWNERDEAD && shm_now() - t0 < 1.0, "... and once it is reaped");
  t0 = shm_now();
  q = shm_read_begin(b);
  check((q & 1u) && shm_now() - t0 < 1.0, "shm_read_begin returns too (the odd sequence) instead of spinning");
  check(shm_block_header(b)->seq & 1u, "seq is odd after a writer died inside");
  t0 = shm_now();
  shm_write_begin(b);
  shm_write_end(b);
  double dt = shm_now() - t0;
  check(!(shm_block_header(b)->seq & 1u) && dt < 1.0, "next writer takes over and completes");
  check(shm_read_begin_checked(b, &q, why, sizeof why) == 0, "the block reads whole again");

  /* a live writer inside for 150 ms is waited for, not called stale */
  pid = fork();
  if (pid == 0) {
    shm_block *wb = NULL;
    char e2[256];
    shm_block_open(s, "t.a", robot, 0, &wb, e2, sizeof e2);
    shm_write_begin(wb);
    shm_sleep_s(0.15);
    shm_write_end(wb);
    _exit(0);
  }
  while (!(shm_block_header(b)->seq & 1u) && !waitpid(pid, NULL, WNOHANG)) shm_sleep_s(0.0005);
  t0 = shm_now();
  rc = shm_read_begin_checked(b, &q, why, sizeof why);
  dt = shm_now() - t0;
  printf("# a live writer inside: the reader waited %.0f ms\n", 1e3 * dt);
  check(rc == 0 && !(q & 1u) && dt > 0.05, "a live writer that takes long is waited for");
  waitpid(pid, NULL, 0);

  /* a writer stopped inside (SIGSTOP: it may never be continued) does not hold a reader either */
  pid = fork();
  if (pid == 0) {
    shm_block *wb = NULL;
    char e2[256];
    shm_block_open(s, "t.a", robot, 0, &wb, e2, sizeof e2);
    shm_write_begin(wb);
    raise(SIGSTOP);
    shm_write_end(wb);
    _exit(0);
  }
  while (!shm_pid_stopped(pid)) shm_sleep_s(0.001);
  t0 = shm_now();
  rc = shm_read_begin_checked(b, &q, why, sizeof why);
  dt = shm_now() - t0;
  snprintf(pidname, sizeof pidname, "pid %d", (int)pid);
  printf("# %s (%.0f ms)\n", why, 1e3 * dt);
  check(rc == -EAGAIN && (q & 1u) && strstr(why, pidname) && strstr(why, "stopped") && dt < 1.0,
        "a reader of a block whose writer is stopped mid-update returns: -EAGAIN, the pid named");
  kill(pid, SIGCONT);
  waitpid(pid, NULL, 0);
  check(shm_read_begin_checked(b, &q, why, sizeof why) == 0, "continued, it finishes: the block reads whole again");

  /* a writer whose pid now belongs to another process (here: this one, with another start time) */
  shm_header *h = shm_block_header(b);
  unsigned long long my_start = 0;
  check(shm_pid_state((int)getpid(), &my_start) == 'R' && my_start > 0, "shm_pid_state: this process runs, a start time");
  h->seq++;
  h->writer_pid = (int32_t)getpid();
  h->writer_start = (uint32_t)my_start + 1;
  t0 = shm_now();
  rc = shm_read_begin_checked(b, &q, why, sizeof why);
  dt = shm_now() - t0;
  check(rc == -EOWNERDEAD && dt < 1.0, "a live writer_pid with another start time (a reused pid) is a dead writer");
  h->writer_start = (uint32_t)my_start;
  h->writer_pid = 0;
  h->seq++;
  check(shm_read_begin_checked(b, &q, why, sizeof why) == 0, "the block reads whole again");
  shm_write_begin(b);
  check(h->writer_pid == (int32_t)getpid() && h->writer_start == (uint32_t)my_start,
        "a writer inside leaves its pid and start time in the header");
  shm_write_end(b);
  shm_block_close(b);
  shm_block_unlink("t.a", robot);
  shm_schema_free(s);
}

static void test_default_schema(void) {
  char err[512];
  shm_schema *s = NULL;
  int rc = shm_schema_load(NULL, &s, err, sizeof err);
  check(rc == 0, "project schema Config/shm.schema loads");
  if (rc < 0) { printf("# %s\n", err); return; }
  const char *need[] = {"dcm.sensor", "dcm.actuator", "sync", "camera.image", "motion", "vision",
                        "world", "game"};
  int all = 1;
  for (size_t i = 0; i < sizeof need / sizeof need[0]; i++) {
    int found = 0;
    for (int k = 0; k < shm_schema_nblocks(s); k++)
      if (strcmp(shm_schema_block_name(s, k), need[i]) == 0) found = 1;
    if (!found) { all = 0; printf("# missing block %s\n", need[i]); }
  }
  check(all, "project schema declares the standard blocks");
  shm_schema_free(s);
}

int main(void) {
  robot = shm_robot_id() + 100000;   /* away from anything a test robot uses */
  snprintf(dir, sizeof dir, "/tmp/hrp_shm_unit.%d", getpid());
  mkdir(dir, 0700);
  test_schema_errors();
  test_create_attach();
  test_replaced();
  test_layout_mismatch();
  test_seqlock_consistency();
  test_dead_writer();
  test_default_schema();
  char cmd[300];
  snprintf(cmd, sizeof cmd, "rm -rf %s", dir);
  const int status = tap_done();
  return system(cmd) != 0 ? 1 : status;
}
