// writer: the recorder's writer thread -- queued items into MCAP files (Modules/mcap), camera frames
// JPEG-compressed straight from YUYV (jpeg_yuyv.c), a new file past file_mb, the oldest deleted past total_mb.
#include "record.h"
#include "jpeg_yuyv.h"
#include "mcap/mcap.h"

#include <algorithm>
#include <atomic>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <ctime>
#include <dirent.h>
#include <string>
#include <sys/stat.h>
#include <unistd.h>
#include <vector>

struct rec_writer {
  rec_opts o;
  const rec_blocks *bs;
  rec_queue *q;
  const rec_doc *docs;
  int ndocs;
  pthread_t thread;
  mcap_writer *mw = nullptr;
  int file_no = 0;
  std::string stem;                       // dir/hrp-<id>-<start time>
  int channel[REC_BLOCKS_MAX];
  int frame_channel = -1;
  int packet_channel[2] = { -1, -1 };     // /gamecontroller, /team.message
  uint32_t seq = 0;
  uint64_t closed_bytes = 0;
  std::atomic<uint64_t> messages{0}, bytes{0}, frames{0}, files{0};
  std::atomic<double> jpeg_cpu{0};
  double last_flush = 0;
  int rc = 0;
  char err[512] = "";
  rec_jpeg *jpeg = nullptr;
  bool frame_error_said = false;
  std::vector<uint8_t> buf;
  ~rec_writer() { rec_jpeg_free(jpeg); }
};

static double wall_now() {
  timespec ts;
  clock_gettime(CLOCK_MONOTONIC, &ts);
  return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

static int fail(rec_writer *w, int code, const char *what) {
  if (w->rc == 0) {
    w->rc = code;
    snprintf(w->err, sizeof w->err, "recorder: %s", what);
  }
  return code;
}

// The file's header part: metadata, the configuration, a schema and a channel per block, the frames' channel.
static int begin_file(rec_writer *w) {
  char path[1200];
  snprintf(path, sizeof path, "%s-%03d.mcap", w->stem.c_str(), w->file_no++);
  char e[300];
  int rc = mcap_writer_open(path, "", w->o.zstd_level, (size_t)(w->o.chunk_kb * 1024), &w->mw, e, sizeof e);
  if (rc < 0) return fail(w, rc, e);
  w->files++;
  char id[16];
  snprintf(id, sizeof id, "%d", w->o.robot_id);
  const char *meta[] = { "robot_id", id, "robot", w->o.robot, "platform", w->o.platform, "camera", w->o.camera,
                         "schema", "Config/shm.schema (each channel's ros2msg definition)" };
  rc = mcap_writer_metadata(w->mw, "hrp", meta, 5);
  std::vector<const char *> files;
  for (int i = 0; i < w->ndocs && rc == 0; i++) {
    const std::string name = std::string("config/") + w->docs[i].name + ".json";
    rc = mcap_writer_attachment(w->mw, name.c_str(), "application/json", 0, w->docs[i].json, strlen(w->docs[i].json));
    files.push_back(w->docs[i].name);
    files.push_back(w->docs[i].files);
  }
  if (rc == 0 && w->ndocs) rc = mcap_writer_metadata(w->mw, "config_files", files.data(), w->ndocs);
  for (int i = 0; i < w->bs->n && rc >= 0; i++) {
    const shmlog_block *m = &w->bs->b[i].msg;
    const int s = mcap_writer_schema(w->mw, m->type_name, "ros2msg", m->def, strlen(m->def));
    const char *cm[] = { "block", m->name };
    rc = s < 0 ? s : (w->channel[i] = mcap_writer_channel(w->mw, s, m->topic, "cdr", cm, 1));
    if (rc >= 0 && w->bs->b[i].has_frame) {
      const int si = mcap_writer_schema(w->mw, SHMLOG_IMAGE_TYPE, "ros2msg", SHMLOG_IMAGE_DEF, strlen(SHMLOG_IMAGE_DEF));
      const std::string topic = std::string(m->topic) + "/jpeg";
      rc = si < 0 ? si : (w->frame_channel = mcap_writer_channel(w->mw, si, topic.c_str(), "cdr", cm, 1));
    }
  }
  if (rc >= 0) {
    const int s = mcap_writer_schema(w->mw, SHMLOG_PACKET_TYPE, "ros2msg", SHMLOG_PACKET_DEF, strlen(SHMLOG_PACKET_DEF));
    const char *gm[] = { "block", REC_PACKETS_BLOCK, "source", "gamecontroller" };
    const char *tm[] = { "block", REC_PACKETS_BLOCK, "source", "team" };
    rc = s < 0 ? s : (w->packet_channel[0] = mcap_writer_channel(w->mw, s, "/gamecontroller", "cdr", gm, 2));
    if (rc >= 0) rc = w->packet_channel[1] = mcap_writer_channel(w->mw, s, "/team.message", "cdr", tm, 2);
  }
  return rc < 0 ? fail(w, rc, mcap_writer_error(w->mw)) : 0;
}

static int end_file(rec_writer *w) {
  if (!w->mw) return 0;
  const uint64_t size = mcap_writer_size(w->mw);
  char e[300];
  const int rc = mcap_writer_close(w->mw, e, sizeof e);
  w->mw = nullptr;
  w->closed_bytes += size;
  return rc < 0 ? fail(w, rc, e) : 0;
}

// The recorder's own files in dir, oldest first (their names sort by start time and number).
static void enforce_total(rec_writer *w) {
  DIR *d = opendir(w->o.dir);
  if (!d) return;
  char prefix[32];
  snprintf(prefix, sizeof prefix, "hrp-%d-", w->o.robot_id);
  std::vector<std::pair<std::string, uint64_t>> have;
  uint64_t total = 0;
  while (dirent *e = readdir(d)) {
    const size_t n = strlen(e->d_name);
    if (strncmp(e->d_name, prefix, strlen(prefix)) != 0 || n < 5 || strcmp(e->d_name + n - 5, ".mcap") != 0) continue;
    const std::string path = std::string(w->o.dir) + "/" + e->d_name;
    struct stat st;
    if (stat(path.c_str(), &st) == 0) {
      have.emplace_back(path, (uint64_t)st.st_size);
      total += (uint64_t)st.st_size;
    }
  }
  closedir(d);
  std::sort(have.begin(), have.end());
  const uint64_t cap = (uint64_t)(w->o.total_mb * 1e6);
  for (size_t i = 0; i + 1 < have.size() && total > cap; i++) {   // never the file being written
    if (unlink(have[i].first.c_str()) == 0) total -= have[i].second;
  }
}

static double thread_cpu() {
  timespec ts;
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
  return (double)ts.tv_sec + 1e-9 * (double)ts.tv_nsec;
}

static int write_frame(rec_writer *w, const rec_item *it) {
  const double c0 = thread_cpu();
  const uint8_t *jpeg;
  size_t len;
  if (rec_jpeg_encode(w->jpeg, it->data, it->width, it->height, w->o.jpeg_quality, &jpeg, &len) < 0) {
    // a frame that cannot be encoded is skipped, not the end of the recording; said once
    if (!w->frame_error_said) fprintf(stderr, "hrp_record: camera frame skipped: %s\n", rec_jpeg_error(w->jpeg));
    w->frame_error_said = true;
    return 0;
  }
  w->buf.resize(len + 256);
  const size_t n = shmlog_image_encode(it->log_time, "camera", "jpeg", jpeg, len, w->buf.data(), w->buf.size());
  w->frames++;
  w->jpeg_cpu = w->jpeg_cpu + (thread_cpu() - c0);
  return mcap_writer_message(w->mw, w->frame_channel, w->seq++, it->log_time, it->publish_time, w->buf.data(), n);
}

static void *run(void *arg) {
  rec_writer *w = static_cast<rec_writer *>(arg);
  w->last_flush = wall_now();
  for (;;) {
    rec_item *it = rec_queue_pop(w->q, 0.1);
    if (!it) {
      pthread_mutex_lock(&w->q->mu);
      const bool done = w->q->closed && !w->q->head;
      pthread_mutex_unlock(&w->q->mu);
      if (done) break;
    } else if (it->kind == REC_ITEM_TICK_END) {
      // a tick is whole: the place to begin a new file, so that no tick is split across two (the open
      // chunk counted at its uncompressed size; a file passes file_mb by at most one tick's messages)
      if (w->rc == 0 && (double)(mcap_writer_size(w->mw) + mcap_writer_pending(w->mw)) > w->o.file_mb * 1e6) {
        if (end_file(w) == 0 && begin_file(w) == 0) enforce_total(w);
      }
    } else if (w->rc == 0) {
      const int ch = it->kind == REC_ITEM_PACKET ? w->packet_channel[it->channel] : w->channel[it->channel];
      const int rc = it->kind == REC_ITEM_FRAME
                         ? write_frame(w, it)
                         : mcap_writer_message(w->mw, ch, w->seq++, it->log_time, it->publish_time, it->data, it->len);
      if (rc < 0) fail(w, rc, mcap_writer_error(w->mw));
      w->messages++;
    }
    free(it);
    if (w->rc) continue;   // drain the queue; the error is reported at the end
    if (wall_now() - w->last_flush >= w->o.flush_s) {
      if (mcap_writer_flush(w->mw) < 0) fail(w, -EIO, mcap_writer_error(w->mw));
      w->last_flush = wall_now();
    }
    w->bytes = w->closed_bytes + (w->mw ? mcap_writer_size(w->mw) : 0);
  }
  end_file(w);
  w->bytes = w->closed_bytes;
  return nullptr;
}

static int mkdirs(const char *dir) {
  std::string p;
  for (const char *c = dir; *c; c++) {
    p += *c;
    if ((c[1] == '/' || c[1] == 0) && mkdir(p.c_str(), 0755) != 0 && errno != EEXIST) return -errno;
  }
  return 0;
}

extern "C" int rec_writer_start(rec_writer **out, const rec_opts *o, const rec_blocks *bs, rec_queue *q,
                                const rec_doc *docs, int ndocs, char *err, size_t errlen) {
  rec_writer *w = new rec_writer();
  if (!(w->jpeg = rec_jpeg_new())) {
    snprintf(err, errlen, "recorder: cannot make a JPEG encoder (TurboJPEG)");
    delete w;
    return -ENOMEM;
  }
  w->o = *o;
  w->bs = bs;
  w->q = q;
  w->docs = docs;
  w->ndocs = ndocs;
  int rc = mkdirs(o->dir);
  if (rc < 0) {
    snprintf(err, errlen, "recorder: cannot create %s: %s", o->dir, strerror(-rc));
    delete w;
    return rc;
  }
  char when[32];
  const time_t now = time(nullptr);
  strftime(when, sizeof when, "%Y%m%d-%H%M%S", localtime(&now));
  w->stem = std::string(o->dir) + "/hrp-" + std::to_string(o->robot_id) + "-" + when;
  if (begin_file(w) < 0) {
    snprintf(err, errlen, "%s", w->err);
    end_file(w);
    delete w;
    return -EIO;
  }
  enforce_total(w);
  if ((rc = pthread_create(&w->thread, nullptr, run, w)) != 0) {
    snprintf(err, errlen, "recorder: cannot start the writer thread: %s", strerror(rc));
    end_file(w);
    delete w;
    return -rc;
  }
  *out = w;
  return 0;
}

extern "C" void rec_writer_figures(rec_writer *w, rec_figures *f) {
  f->messages = w->messages;
  f->bytes = w->bytes;
  f->frames = w->frames;
  f->files = w->files;
  f->jpeg_cpu = w->jpeg_cpu;
}

extern "C" int rec_writer_join(rec_writer *w, rec_figures *f, char *err, size_t errlen) {
  pthread_join(w->thread, nullptr);
  rec_writer_figures(w, f);
  const int rc = w->rc;
  if (rc < 0) snprintf(err, errlen, "%s", w->err);
  delete w;
  return rc;
}
