/* hrp_record: records every shm block of ROBOT_ID into MCAP files (see record.h and README.md).
 *   hrp_record [--dir DIR] [--seconds S] [--camera jpeg|raw|off] [--file-mb MB] [--total-mb MB] [--lockstep] [--quiet]
 * --lockstep: in a lockstep run, record every tick as a lockstep observer (observer.c).
 * Settings: Config/common/recorder.lua (overlaid like every concern). Stops on SIGINT / SIGTERM
 * (closing the file properly) and prints its figures. */
#include "record.h"
#include "dcm/dcm.h"

#include <errno.h>
#include <malloc.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/resource.h>
#include <time.h>
#include <unistd.h>

_Static_assert(sizeof(((rec_opts *)0)->exclude[0]) == DCM_NAME_MAX, "rec_opts.exclude rows are DCM_NAME_MAX");
_Static_assert(sizeof(((rec_opts *)0)->concerns[0]) == DCM_NAME_MAX, "rec_opts.concerns rows are DCM_NAME_MAX");

static volatile sig_atomic_t g_stop;
static void on_signal(int s) { (void)s; g_stop = 1; }

static double cpu_seconds(void) {
  struct rusage ru;
  getrusage(RUSAGE_SELF, &ru);
  return (double)ru.ru_utime.tv_sec + 1e-6 * (double)ru.ru_utime.tv_usec + (double)ru.ru_stime.tv_sec +
         1e-6 * (double)ru.ru_stime.tv_usec;
}

static uint64_t wall_ns(void) {
  struct timespec ts;
  clock_gettime(CLOCK_REALTIME, &ts);
  return (uint64_t)ts.tv_sec * 1000000000ull + (uint64_t)ts.tv_nsec;
}

static int read_config(rec_opts *o, char *err, size_t errlen) {
  dcm_config *c;
  int rc = dcm_config_load("recorder", NULL, NULL, &c, err, errlen);
  if (rc < 0) return rc;
  char dir[512];
  if ((rc = dcm_config_str(c, "dir", dir, sizeof dir, err, errlen)) < 0 ||
      (rc = dcm_config_num(c, "file_mb", &o->file_mb, err, errlen)) < 0 ||
      (rc = dcm_config_num(c, "total_mb", &o->total_mb, err, errlen)) < 0 ||
      (rc = dcm_config_num(c, "chunk_kb", &o->chunk_kb, err, errlen)) < 0 ||
      (rc = dcm_config_num(c, "flush_s", &o->flush_s, err, errlen)) < 0 ||
      (rc = dcm_config_num(c, "queue_mb", &o->queue_mb, err, errlen)) < 0 ||
      (rc = dcm_config_int(c, "zstd_level", &o->zstd_level, err, errlen)) < 0 ||
      (rc = dcm_config_int(c, "jpeg_quality", &o->jpeg_quality, err, errlen)) < 0 ||
      (rc = dcm_config_num(c, "history_s", &o->history_s, err, errlen)) < 0 ||
      (rc = dcm_config_str(c, "camera", o->camera, sizeof o->camera, err, errlen)) < 0 ||
      (rc = dcm_config_str(c, "camera_block", o->camera_block, sizeof o->camera_block, err, errlen)) < 0 ||
      (rc = dcm_config_str(c, "camera_field", o->camera_field, sizeof o->camera_field, err, errlen)) < 0 ||
      (rc = o->nexclude = dcm_config_strs(c, "exclude", (char(*)[DCM_NAME_MAX])o->exclude, 0, REC_BLOCKS_MAX, err,
                                          errlen)) < 0 ||
      (rc = o->nconcerns = dcm_config_strs(c, "concerns", (char(*)[DCM_NAME_MAX])o->concerns, 0, REC_CONCERNS_MAX,
                                           err, errlen)) < 0)
    goto done;
  if (strcmp(o->camera, "jpeg") && strcmp(o->camera, "raw") && strcmp(o->camera, "off")) {
    rc = dcm_config_fail(c, err, errlen, "key 'camera' must be 'jpeg', 'raw' or 'off', got '%s'", o->camera);
    goto done;
  }
  if (!(o->file_mb > 0) || !(o->total_mb >= o->file_mb) || !(o->queue_mb > 0) || o->jpeg_quality < 0 ||
      o->jpeg_quality > 100) {
    rc = dcm_config_fail(c, err, errlen, "need file_mb > 0, total_mb >= file_mb, queue_mb > 0, jpeg_quality 0..100");
    goto done;
  }
  if (dir[0] == '/') snprintf(o->dir, sizeof o->dir, "%s", dir);
  else snprintf(o->dir, sizeof o->dir, "%s/%s", dcm_root(), dir);
  snprintf(o->robot, sizeof o->robot, "%s", dcm_config_robot(c));
  snprintf(o->platform, sizeof o->platform, "%s", dcm_config_platform(c));
done:
  dcm_config_free(c);
  return rc < 0 ? rc : 0;
}

static int usage(const char *msg) {
  if (msg) fprintf(stderr, "hrp_record: %s\n", msg);
  fprintf(stderr, "usage: hrp_record [--dir DIR] [--seconds S] [--camera jpeg|raw|off] [--file-mb MB] [--total-mb MB] "
          "[--lockstep] [--quiet]\n");
  return 2;
}

int main(int argc, char **argv) {
  static rec_opts o;
  static rec_blocks bs;
  static rec_doc docs[REC_CONCERNS_MAX];
  static rec_queue q;
  static rec_history hist;
  static rec_observer ob;
  static rec_packets pk;
  char err[1024];
  const char *dir = NULL, *camera = NULL;
  double file_mb = 0, total_mb = 0;
  int lockstep = 0;
  o.seconds = -1;
  for (int i = 1; i < argc; i++) {
    if (!strcmp(argv[i], "--dir") && i + 1 < argc) dir = argv[++i];
    else if (!strcmp(argv[i], "--seconds") && i + 1 < argc) o.seconds = atof(argv[++i]);
    else if (!strcmp(argv[i], "--camera") && i + 1 < argc) camera = argv[++i];
    else if (!strcmp(argv[i], "--file-mb") && i + 1 < argc) file_mb = atof(argv[++i]);
    else if (!strcmp(argv[i], "--total-mb") && i + 1 < argc) total_mb = atof(argv[++i]);
    else if (!strcmp(argv[i], "--quiet")) o.quiet = 1;
    else if (!strcmp(argv[i], "--lockstep")) lockstep = 1;
    else return usage(argv[i][0] == '-' && strcmp(argv[i], "-h") && strcmp(argv[i], "--help") ? "unknown option" : NULL);
  }
  /* a camera frame (600 kB) per item: kept on the heap and reused rather than mapped and faulted in
   * afresh for every frame */
  mallopt(M_MMAP_THRESHOLD, 8 << 20);
  o.robot_id = shm_robot_id();
  if (read_config(&o, err, sizeof err) < 0) {
    fprintf(stderr, "hrp_record: %s\n", err);
    return 1;
  }
  if (dir) snprintf(o.dir, sizeof o.dir, "%s", dir);
  if (file_mb > 0) o.file_mb = file_mb;
  if (total_mb > 0) o.total_mb = total_mb;
  if (o.total_mb < o.file_mb) return usage("--total-mb must be at least --file-mb");
  if (camera) {
    if (strcmp(camera, "jpeg") && strcmp(camera, "raw") && strcmp(camera, "off")) return usage("--camera: jpeg, raw or off");
    snprintf(o.camera, sizeof o.camera, "%s", camera);
  }
  struct sigaction sa;
  memset(&sa, 0, sizeof sa);
  sa.sa_handler = on_signal;
  sigaction(SIGINT, &sa, NULL);
  sigaction(SIGTERM, &sa, NULL);

  int ndocs = 0, rc;
  rec_writer *w = NULL;
  shm_block *stats = NULL;
  if ((rc = rec_blocks_open(&bs, &o, err, sizeof err)) < 0 ||
      (rc = ndocs = rec_config_docs(&o, docs, REC_CONCERNS_MAX, err, sizeof err)) < 0 ||
      (rc = shm_block_open(bs.schema, "recorder", o.robot_id, SHM_OPEN_CREATE, &stats, err, sizeof err)) < 0) {
    fprintf(stderr, "hrp_record: %s\n", err);
    rec_blocks_close(&bs);
    return 1;
  }
  shm_block *sensor = NULL;
  for (int i = 0; i < bs.n; i++)
    if (!strcmp(shm_block_name(bs.b[i].blk), "dcm.sensor")) sensor = bs.b[i].blk;
  const double *time_p = sensor ? (const double *)shm_field_require(sensor, "time", SHM_F64, 1, err, sizeof err) : NULL;
  const uint32_t *tick_p = sensor ? (const uint32_t *)shm_field_require(sensor, "tick", SHM_U32, 1, err, sizeof err) : NULL;
  int32_t *s_pid = (int32_t *)shm_field_ptr(stats, "pid", NULL, NULL);
  uint64_t *s_msg = (uint64_t *)shm_field_ptr(stats, "messages", NULL, NULL);
  uint64_t *s_bytes = (uint64_t *)shm_field_ptr(stats, "bytes", NULL, NULL);
  uint32_t *s_drop = (uint32_t *)shm_field_ptr(stats, "dropped", NULL, NULL);
  uint32_t *s_miss = (uint32_t *)shm_field_ptr(stats, "missed_ticks", NULL, NULL);
  uint32_t *s_frames = (uint32_t *)shm_field_ptr(stats, "frames", NULL, NULL);
  uint32_t *s_files = (uint32_t *)shm_field_ptr(stats, "files", NULL, NULL);
  double *s_rate = (double *)shm_field_ptr(stats, "rate", NULL, NULL);
  double *s_cpu = (double *)shm_field_ptr(stats, "cpu", NULL, NULL);
  if (!time_p || !tick_p || !s_pid || !s_msg || !s_bytes || !s_drop || !s_miss || !s_frames || !s_files || !s_rate ||
      !s_cpu) {
    fprintf(stderr, "hrp_record: the schema lacks dcm.sensor time / tick or a field of block 'recorder'\n");
    rec_blocks_close(&bs);
    return 1;
  }
  /* the rings hold a sample per DCM period of the body */
  double period = 0;
  dcm_config *rcfg;
  if (dcm_config_load("robot", NULL, NULL, &rcfg, err, sizeof err) == 0) {
    if (dcm_config_num(rcfg, "period", &period, err, sizeof err) < 0) period = 0;
    dcm_config_free(rcfg);
  }
  if (rec_packets_open(&pk, bs.schema, o.robot_id, err, sizeof err) < 0)
    fprintf(stderr, "hrp_record: %s (no GameController or team packets)\n", err);
  if (rec_history_open(&hist, &bs, &o, period, err, sizeof err) < 0) fprintf(stderr, "hrp_record: %s (no history)\n", err);
  if (lockstep && rec_observer_join(&ob, bs.schema, o.robot_id, err, sizeof err) < 0) {
    fprintf(stderr, "hrp_record: %s\n", err);
    rec_blocks_close(&bs);
    return 1;
  }
  rec_queue_init(&q, (size_t)(o.queue_mb * 1e6));
  q.wait_for_room = lockstep;
  if (rec_writer_start(&w, &o, &bs, &q, docs, ndocs, err, sizeof err) < 0) {
    fprintf(stderr, "hrp_record: %s\n", err);
    rec_blocks_close(&bs);
    return 1;
  }
  if (!o.quiet) fprintf(stderr, "hrp_record: robot %d: %d blocks into %s (camera %s)\n", o.robot_id, bs.n, o.dir, o.camera);

  const double t0 = shm_now(), cpu0 = cpu_seconds();
  double next_stats = t0 + 1, cpu_last = cpu0, t_last = t0;
  uint64_t bytes_last = 0;
  uint32_t writes = 0;
  *s_pid = (int32_t)getpid();
  while (!g_stop) {
    uint32_t observed = 0;
    int sample = 1;
    if (lockstep && (observed = rec_observer_wait(&ob, 0.05)) == 0 && *ob.lockstep == 1) sample = 0;
    else if (!observed) writes = shm_wait_write(sensor, writes, 0.05);
    if (sample) {
      const double t = *time_p;
      const uint64_t log_time = t > 0 ? (uint64_t)(t * 1e9 + 0.5) : 0, wall = wall_ns();
      if (rec_blocks_sample(&bs, &q, &hist, log_time, wall) + rec_packets_sample(&pk, &q, log_time, wall) > 0)
        rec_queue_tick_end(&q);
      if (observed) rec_observer_done(&ob, observed);
    }
    const double now = shm_now();
    if (now >= next_stats) {
      rec_figures f;
      rec_writer_figures(w, &f);
      const double cpu = cpu_seconds();
      shm_write_begin(stats);
      *s_msg = f.messages;
      *s_bytes = f.bytes;
      *s_drop = (uint32_t)rec_queue_dropped(&q);
      *s_miss = (uint32_t)bs.missed;
      *s_frames = (uint32_t)f.frames;
      *s_files = (uint32_t)f.files;
      *s_rate = (double)(f.bytes - bytes_last) / (now - t_last);
      *s_cpu = (cpu - cpu_last) / (now - t_last);
      shm_write_end(stats);
      bytes_last = f.bytes;
      cpu_last = cpu;
      t_last = now;
      next_stats = now + 1;
    }
    if (o.seconds >= 0 && now - t0 >= o.seconds) break;
  }
  const double elapsed = shm_now() - t0;
  rec_observer_leave(&ob);
  rec_queue_close(&q);
  rec_figures f;
  rc = rec_writer_join(w, &f, err, sizeof err);
  const double cpu = cpu_seconds() - cpu0;
  *s_pid = 0;
  if (rc < 0) fprintf(stderr, "hrp_record: %s\n", err);
  rec_history_close(&hist);
  rec_packets_close(&pk);
  rec_blocks_close(&bs);
  rec_config_free(docs, ndocs);
  printf("hrp_record: %.1f s: %llu messages, %llu camera frames, %llu bytes in %llu file(s) = %.0f bytes/s; "
         "dropped %llu, missed ticks %llu; packets %llu, lost %llu; cpu %.3f s = %.2f%% of one core "
         "(JPEG %.2f ms/frame)\n",
         elapsed, (unsigned long long)f.messages, (unsigned long long)f.frames, (unsigned long long)f.bytes,
         (unsigned long long)f.files, (double)f.bytes / elapsed, (unsigned long long)rec_queue_dropped(&q),
         (unsigned long long)bs.missed, (unsigned long long)pk.taken, (unsigned long long)pk.lost, cpu,
         100 * cpu / elapsed, f.frames ? 1e3 * f.jpeg_cpu / (double)f.frames : 0.0);
  shm_block_close(stats);
  return rc < 0 ? 1 : 0;
}
