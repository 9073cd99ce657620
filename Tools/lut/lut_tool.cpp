// lut_tool: builds, saves and checks the colour lookup tables of the vision pipeline.
//
//   lut_tool colors [--config FILE] -o OUT.lut
//       the table of the colour boxes in the vision config (Lib/Config.lua layers: Config/common/vision.lua ...)
//   lut_tool train [--config FILE] [--base IN.lut | --colors] [--grow N] -o OUT.lut IMAGE MASK [...]
//       a table from labelled example images: MASK is an image of the same size in which labelled
//       pixels are painted in a colour's `display` RGB (from the config); other pixels are ignored.
//       Each table cell takes the colour most of its pixels were labelled with; then empty cells
//       within N cells (default 1) of labelled ones take their neighbours' majority. Cells no
//       example reached keep the base table's entry (--base file, or --colors: the colour boxes).
//   lut_tool render [--config FILE] [--lut IN.lut] [--scale S] -o OUT.png (IMAGE | --shm)
//       labels a frame (an image file, a raw .yuyv file with --size WxH, or the robot's current
//       camera.image with --shm) and writes the frame and its label image side by side; prints
//       the pixel count of every colour.
//   lut_tool frame -o OUT.(png|yuyv) --shm
//       saves the robot's current camera frame (to label it for training).
//
// Image files are read and written with OpenCV; colours are converted between RGB and YUV with
// BT.601 full-range formulas (the same as the sim renderer and UVC cameras' YUYV).
#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <string>
#include <vector>

extern "C" {
#include <lauxlib.h>
#include <lua.h>
#include <lualib.h>

#include "imageproc/imageproc.h"
#include "shm/shm.h"
}

namespace {

struct Color {
  std::string name;
  int bit = 0;
  int y[2] = {0, 0}, u[2] = {0, 0}, v[2] = {0, 0};
  int rgb[3] = {255, 255, 255};
};

struct VisionConfig {
  std::string file;
  std::vector<Color> colors;
  std::string lut;   // "" when the config builds the table from its boxes
  int scale = 2;
};

[[noreturn]] void die(const std::string &msg) {
  std::fprintf(stderr, "lut_tool: %s\n", msg.c_str());
  std::exit(1);
}

std::string root() {
  const char *r = std::getenv("HRP_ROOT");
  return r && *r ? r : HRP_ROOT_DEFAULT;
}

// ---------------------------------------------------------------- config (a Lua file)

int int_field(lua_State *L, int idx, const char *key, const std::string &where) {
  lua_getfield(L, idx, key);
  if (!lua_isnumber(L, -1)) die(where + ": '" + key + "' must be a number");
  int v = (int)lua_tonumber(L, -1);
  lua_pop(L, 1);
  return v;
}

void pair_field(lua_State *L, int idx, const char *key, int out[2], int n, const std::string &where) {
  lua_getfield(L, idx, key);
  if (!lua_istable(L, -1)) die(where + ": '" + key + "' must be a table of " + std::to_string(n) + " numbers");
  for (int i = 0; i < n; i++) {
    lua_rawgeti(L, -1, i + 1);
    if (!lua_isnumber(L, -1)) die(where + ": '" + key + "' must be a table of " + std::to_string(n) + " numbers");
    out[i] = (int)lua_tonumber(L, -1);
    if (out[i] < 0 || out[i] > 255) die(where + ": '" + key + "' values must be within 0..255");
    lua_pop(L, 1);
  }
  lua_pop(L, 1);
}

// A vision config file given by name, or else the robot's vision config (Lib/Config.lua's layers).
VisionConfig load_config(std::string file) {
  VisionConfig cfg;
  lua_State *L = luaL_newstate();
  luaL_openlibs(L);
  if (file.empty()) {
    const char *script =
        "local root = ...\n"
        "package.path = root .. '/Lib/?.lua;' .. package.path\n"
        "local t, files = require('Config').export('vision')\n"
        "return files, t\n";
    if (luaL_loadstring(L, script) != 0) die(lua_tostring(L, -1));
    lua_pushstring(L, root().c_str());
    if (lua_pcall(L, 1, 2, 0) != 0) die(lua_tostring(L, -1));
    file = lua_tostring(L, -2);
  } else if (luaL_loadfile(L, file.c_str()) != 0 || lua_pcall(L, 0, 1, 0) != 0) {
    die(lua_tostring(L, -1));
  }
  cfg.file = file;
  if (!lua_istable(L, -1)) die(file + ": must return a table");
  int t = lua_gettop(L);
  lua_getfield(L, t, "colors");
  if (!lua_istable(L, -1)) die(file + ": missing key 'colors'");
  int ct = lua_gettop(L);
  for (int i = 1;; i++) {
    lua_rawgeti(L, ct, i);
    if (lua_isnil(L, -1)) { lua_pop(L, 1); break; }
    int e = lua_gettop(L);
    Color c;
    std::string where = file + ": colors[" + std::to_string(i) + "]";
    lua_getfield(L, e, "name");
    if (!lua_isstring(L, -1)) die(where + ": 'name' must be a string");
    c.name = lua_tostring(L, -1);
    lua_pop(L, 1);
    where = file + ": colour '" + c.name + "'";
    c.bit = int_field(L, e, "bit", where);
    if (c.bit < 1 || c.bit > 255) die(where + ": 'bit' must be 1..255");
    pair_field(L, e, "y", c.y, 2, where);
    pair_field(L, e, "u", c.u, 2, where);
    pair_field(L, e, "v", c.v, 2, where);
    lua_getfield(L, e, "display");
    bool has_display = lua_istable(L, -1);
    lua_pop(L, 1);
    if (has_display) pair_field(L, e, "display", c.rgb, 3, where);
    cfg.colors.push_back(c);
    lua_pop(L, 1);
  }
  lua_pop(L, 1);
  lua_getfield(L, t, "lut");
  if (lua_isstring(L, -1)) cfg.lut = lua_tostring(L, -1);
  lua_pop(L, 1);
  lua_getfield(L, t, "scale");
  if (lua_isnumber(L, -1)) cfg.scale = (int)lua_tonumber(L, -1);
  lua_pop(L, 1);
  lua_close(L);
  if (cfg.colors.empty()) die(file + ": 'colors' is empty");
  return cfg;
}

// ---------------------------------------------------------------- colours

inline uint8_t clamp8(double v) { return (uint8_t)std::min(255.0, std::max(0.0, std::round(v))); }

void rgb_to_yuv(int r, int g, int b, uint8_t *y, uint8_t *u, uint8_t *v) {
  *y = clamp8(0.299 * r + 0.587 * g + 0.114 * b);
  *u = clamp8(128 - 0.168736 * r - 0.331264 * g + 0.5 * b);
  *v = clamp8(128 + 0.5 * r - 0.418688 * g - 0.081312 * b);
}

void yuv_to_bgr(int y, int u, int v, uint8_t *bgr) {
  bgr[2] = clamp8(y + 1.402 * (v - 128));
  bgr[1] = clamp8(y - 0.344136 * (u - 128) - 0.714136 * (v - 128));
  bgr[0] = clamp8(y + 1.772 * (u - 128));
}

// A frame as YUYV (width even) and its size.
struct Frame {
  int w = 0, h = 0;
  std::vector<uint8_t> yuyv;
};

Frame from_bgr(const cv::Mat &bgr) {
  Frame f;
  f.w = bgr.cols & ~1;
  f.h = bgr.rows;
  f.yuyv.resize((size_t)f.w * f.h * 2);
  for (int y = 0; y < f.h; y++) {
    const uint8_t *row = bgr.ptr<uint8_t>(y);
    uint8_t *out = &f.yuyv[(size_t)y * f.w * 2];
    for (int x = 0; x < f.w; x += 2) {
      uint8_t y0, u0, v0, y1, u1, v1;
      rgb_to_yuv(row[3 * x + 2], row[3 * x + 1], row[3 * x], &y0, &u0, &v0);
      rgb_to_yuv(row[3 * x + 5], row[3 * x + 4], row[3 * x + 3], &y1, &u1, &v1);
      out[2 * x] = y0;
      out[2 * x + 1] = (uint8_t)((u0 + u1 + 1) / 2);
      out[2 * x + 2] = y1;
      out[2 * x + 3] = (uint8_t)((v0 + v1 + 1) / 2);
    }
  }
  return f;
}

cv::Mat to_bgr(const Frame &f) {
  cv::Mat m(f.h, f.w, CV_8UC3);
  for (int y = 0; y < f.h; y++) {
    const uint8_t *p = &f.yuyv[(size_t)y * f.w * 2];
    uint8_t *row = m.ptr<uint8_t>(y);
    for (int x = 0; x < f.w; x += 2) {
      yuv_to_bgr(p[2 * x], p[2 * x + 1], p[2 * x + 3], row + 3 * x);
      yuv_to_bgr(p[2 * x + 2], p[2 * x + 1], p[2 * x + 3], row + 3 * x + 3);
    }
  }
  return m;
}

bool ends_with(const std::string &s, const std::string &suf) {
  return s.size() >= suf.size() && s.compare(s.size() - suf.size(), suf.size(), suf) == 0;
}

Frame read_frame(const std::string &path, int w, int h) {
  if (ends_with(path, ".yuyv")) {
    if (w <= 0 || h <= 0) die(path + ": a raw .yuyv frame needs --size WxH");
    std::ifstream in(path, std::ios::binary);
    if (!in) die(path + ": cannot open");
    Frame f;
    f.w = w;
    f.h = h;
    f.yuyv.resize((size_t)w * h * 2);
    in.read((char *)f.yuyv.data(), (std::streamsize)f.yuyv.size());
    if ((size_t)in.gcount() != f.yuyv.size()) die(path + ": shorter than a " + std::to_string(w) + "x" +
                                                  std::to_string(h) + " YUYV frame");
    return f;
  }
  cv::Mat bgr = cv::imread(path, cv::IMREAD_COLOR);
  if (bgr.empty()) die(path + ": cannot read the image");
  return from_bgr(bgr);
}

// The robot's current camera.image frame.
Frame shm_frame() {
  char err[512];
  shm_schema *schema = nullptr;
  shm_block *b = nullptr;
  if (shm_schema_load(nullptr, &schema, err, sizeof err) < 0) die(err);
  if (shm_block_open(schema, "camera.image", shm_robot_id(), 0, &b, err, sizeof err) < 0)
    die(std::string(err) + " (is a camera or the sim running for ROBOT_ID?)");
  int count = 0;
  int32_t *w = (int32_t *)shm_field_require(b, "width", SHM_I32, 1, err, sizeof err);
  int32_t *h = w ? (int32_t *)shm_field_require(b, "height", SHM_I32, 1, err, sizeof err) : nullptr;
  uint8_t *pix = h ? (uint8_t *)shm_field_ptr(b, "yuyv", nullptr, &count) : nullptr;
  if (!pix) die(err);
  Frame f;
  uint32_t seq;
  do {
    seq = shm_read_begin(b);
    f.w = *w;
    f.h = *h;
    if (f.w <= 0 || f.h <= 0 || (long)f.w * f.h * 2 > count) die("camera.image holds no frame yet");
    f.yuyv.assign(pix, pix + (size_t)f.w * f.h * 2);
  } while (shm_read_retry(b, seq));
  shm_block_close(b);
  shm_schema_free(schema);
  return f;
}

void save_lut(const std::string &path, const std::vector<uint8_t> &lut) {
  char err[512];
  if (img_lut_save(path.c_str(), lut.data(), err, sizeof err) < 0) die(err);
}

std::vector<uint8_t> color_lut(const VisionConfig &cfg) {
  std::vector<uint8_t> lut(IMG_LUT_SIZE, 0);
  std::vector<img_color_range> r;
  for (const Color &c : cfg.colors)
    r.push_back({(uint8_t)c.bit, (uint8_t)c.y[0], (uint8_t)c.y[1], (uint8_t)c.u[0], (uint8_t)c.u[1],
                 (uint8_t)c.v[0], (uint8_t)c.v[1]});
  if (img_lut_add_ranges(lut.data(), r.data(), (int)r.size()) < 0) die(cfg.file + ": a colour box has min > max");
  return lut;
}

// ---------------------------------------------------------------- commands

struct Args {
  std::string config, out, base, lut, size;
  bool colors = false, use_shm = false;
  int grow = 1, scale = 0;
  std::vector<std::string> files;
};

Args parse(int argc, char **argv, int first) {
  Args a;
  for (int i = first; i < argc; i++) {
    std::string s = argv[i];
    auto val = [&]() -> std::string {
      if (i + 1 >= argc) die(s + " needs a value");
      return argv[++i];
    };
    if (s == "--config") a.config = val();
    else if (s == "-o") a.out = val();
    else if (s == "--base") a.base = val();
    else if (s == "--lut") a.lut = val();
    else if (s == "--size") a.size = val();
    else if (s == "--grow") a.grow = std::atoi(val().c_str());
    else if (s == "--scale") a.scale = std::atoi(val().c_str());
    else if (s == "--colors") a.colors = true;
    else if (s == "--shm") a.use_shm = true;
    else if (!s.empty() && s[0] == '-') die("unknown option " + s);
    else a.files.push_back(s);
  }
  return a;
}

void size_of(const Args &a, int *w, int *h) {
  *w = *h = 0;
  if (!a.size.empty() && std::sscanf(a.size.c_str(), "%dx%d", w, h) != 2) die("--size must be WxH");
}

int cmd_colors(const Args &a) {
  if (a.out.empty()) die("colors: -o OUT.lut required");
  VisionConfig cfg = load_config(a.config);
  save_lut(a.out, color_lut(cfg));
  std::printf("wrote %s from %zu colour boxes of %s\n", a.out.c_str(), cfg.colors.size(), cfg.file.c_str());
  return 0;
}

int cmd_train(const Args &a) {
  if (a.out.empty()) die("train: -o OUT.lut required");
  if (a.files.empty() || a.files.size() % 2) die("train: give IMAGE MASK pairs");
  VisionConfig cfg = load_config(a.config);
  const int nc = (int)cfg.colors.size();
  std::vector<uint8_t> lut(IMG_LUT_SIZE, 0);
  if (!a.base.empty()) {
    char err[512];
    if (img_lut_load(a.base.c_str(), lut.data(), err, sizeof err) < 0) die(err);
  } else if (a.colors) {
    lut = color_lut(cfg);
  }
  std::vector<uint32_t> votes((size_t)IMG_LUT_SIZE * nc, 0);
  int w, h;
  size_of(a, &w, &h);
  long labelled = 0;
  for (size_t k = 0; k < a.files.size(); k += 2) {
    Frame f = read_frame(a.files[k], w, h);
    cv::Mat mask = cv::imread(a.files[k + 1], cv::IMREAD_COLOR);
    if (mask.empty()) die(a.files[k + 1] + ": cannot read the mask");
    if ((mask.cols & ~1) != f.w || mask.rows != f.h)
      die(a.files[k + 1] + ": mask is " + std::to_string(mask.cols) + "x" + std::to_string(mask.rows) +
          ", image is " + std::to_string(f.w) + "x" + std::to_string(f.h));
    for (int y = 0; y < f.h; y++) {
      const uint8_t *m = mask.ptr<uint8_t>(y);
      const uint8_t *p = &f.yuyv[(size_t)y * f.w * 2];
      for (int x = 0; x < f.w; x++) {
        int b = m[3 * x], g = m[3 * x + 1], r = m[3 * x + 2];
        for (int c = 0; c < nc; c++) {
          const int *d = cfg.colors[c].rgb;
          if (std::abs(r - d[0]) <= 8 && std::abs(g - d[1]) <= 8 && std::abs(b - d[2]) <= 8) {
            const uint8_t *pair = p + (x / 2) * 4;
            uint32_t idx = img_lut_index(pair[(x & 1) * 2], pair[1], pair[3]);
            votes[(size_t)idx * nc + c]++;
            labelled++;
            break;
          }
        }
      }
    }
  }
  // each voted cell: the colour with the most votes
  std::vector<int> best(IMG_LUT_SIZE, -1);
  int voted = 0;
  for (int i = 0; i < IMG_LUT_SIZE; i++) {
    uint32_t top = 0;
    for (int c = 0; c < nc; c++)
      if (votes[(size_t)i * nc + c] > top) { top = votes[(size_t)i * nc + c]; best[i] = c; }
    if (best[i] >= 0) voted++;
  }
  // grow into empty neighbouring cells (6-neighbourhood in the 64^3 grid), majority of neighbours
  int grown = 0;
  for (int step = 0; step < a.grow; step++) {
    std::vector<int> next = best;
    for (int y = 0; y < 64; y++)
      for (int u = 0; u < 64; u++)
        for (int v = 0; v < 64; v++) {
          int i = (y << 12) | (u << 6) | v;
          if (best[i] >= 0) continue;
          int count[8] = {0};
          const int d[6][3] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
          for (const auto &o : d) {
            int yy = y + o[0], uu = u + o[1], vv = v + o[2];
            if (yy < 0 || uu < 0 || vv < 0 || yy > 63 || uu > 63 || vv > 63) continue;
            int n = best[(yy << 12) | (uu << 6) | vv];
            if (n >= 0 && n < 8) count[n]++;
          }
          int bc = -1, bn = 0;
          for (int c = 0; c < nc && c < 8; c++)
            if (count[c] > bn) { bn = count[c]; bc = c; }
          if (bc >= 0) { next[i] = bc; grown++; }
        }
    best.swap(next);
  }
  for (int i = 0; i < IMG_LUT_SIZE; i++)
    if (best[i] >= 0) lut[i] = (uint8_t)cfg.colors[best[i]].bit;
  save_lut(a.out, lut);
  std::printf("wrote %s: %ld labelled pixels, %d cells voted, %d grown\n", a.out.c_str(), labelled, voted,
              grown);
  return 0;
}

int cmd_render(const Args &a) {
  if (a.out.empty()) die("render: -o OUT.png required");
  VisionConfig cfg = load_config(a.config);
  std::vector<uint8_t> lut(IMG_LUT_SIZE, 0);
  std::string lut_path = !a.lut.empty() ? a.lut : cfg.lut.empty() ? "" : (cfg.lut[0] == '/' ? cfg.lut : root() + "/" + cfg.lut);
  if (!lut_path.empty()) {
    char err[512];
    if (img_lut_load(lut_path.c_str(), lut.data(), err, sizeof err) < 0) die(err);
  } else {
    lut = color_lut(cfg);
  }
  int w, h;
  size_of(a, &w, &h);
  Frame f;
  if (a.use_shm) f = shm_frame();
  else if (a.files.size() == 1) f = read_frame(a.files[0], w, h);
  else die("render: give one IMAGE or --shm");
  int scale = a.scale > 0 ? a.scale : cfg.scale;
  if (scale < 2 || scale % 2) die("render: scale must be even");
  int wa = f.w / scale, ha = f.h / scale;
  std::vector<uint8_t> labels((size_t)wa * ha);
  if (img_label_yuyv(f.yuyv.data(), f.w, f.h, lut.data(), scale, labels.data()) < 0) die("render: bad frame size");
  cv::Mat lab(ha, wa, CV_8UC3, cv::Scalar(0, 0, 0));
  std::vector<long> counts(cfg.colors.size(), 0);
  for (int y = 0; y < ha; y++)
    for (int x = 0; x < wa; x++) {
      uint8_t l = labels[(size_t)y * wa + x];
      for (size_t c = 0; c < cfg.colors.size(); c++)
        if (l & cfg.colors[c].bit) {
          counts[c]++;
          cv::Vec3b &px = lab.at<cv::Vec3b>(y, x);
          if (px == cv::Vec3b(0, 0, 0))
            px = cv::Vec3b((uint8_t)cfg.colors[c].rgb[2], (uint8_t)cfg.colors[c].rgb[1], (uint8_t)cfg.colors[c].rgb[0]);
        }
    }
  cv::Mat big, both;
  cv::resize(lab, big, cv::Size(wa * scale, ha * scale), 0, 0, cv::INTER_NEAREST);
  cv::Mat frame = to_bgr(f)(cv::Rect(0, 0, wa * scale, ha * scale));
  cv::hconcat(frame, big, both);
  int ty = 20;
  for (size_t c = 0; c < cfg.colors.size(); c++, ty += 20) {
    const int *d = cfg.colors[c].rgb;
    cv::putText(both, cfg.colors[c].name, cv::Point(wa * scale + 8, ty), cv::FONT_HERSHEY_SIMPLEX, 0.5,
                cv::Scalar(d[2], d[1], d[0]), 1, cv::LINE_AA);
  }
  if (!cv::imwrite(a.out, both)) die(a.out + ": cannot write");
  std::printf("wrote %s (%dx%d frame, labels %dx%d)\n", a.out.c_str(), f.w, f.h, wa, ha);
  for (size_t c = 0; c < cfg.colors.size(); c++) std::printf("%s %ld\n", cfg.colors[c].name.c_str(), counts[c]);
  return 0;
}

int cmd_frame(const Args &a) {
  if (a.out.empty() || !a.use_shm) die("frame: -o OUT.(png|yuyv) --shm required");
  Frame f = shm_frame();
  if (ends_with(a.out, ".yuyv")) {
    std::ofstream o(a.out, std::ios::binary);
    o.write((const char *)f.yuyv.data(), (std::streamsize)f.yuyv.size());
    if (!o) die(a.out + ": cannot write");
  } else if (!cv::imwrite(a.out, to_bgr(f))) {
    die(a.out + ": cannot write");
  }
  std::printf("wrote %s (%dx%d)\n", a.out.c_str(), f.w, f.h);
  return 0;
}

void usage() {
  std::fprintf(stderr,
               "usage: lut_tool colors [--config FILE] -o OUT.lut\n"
               "       lut_tool train [--config FILE] [--base IN.lut | --colors] [--grow N] [--size WxH] "
               "-o OUT.lut IMAGE MASK [IMAGE MASK ...]\n"
               "       lut_tool render [--config FILE] [--lut IN.lut] [--scale S] [--size WxH] -o OUT.png "
               "(IMAGE | --shm)\n"
               "       lut_tool frame -o OUT.(png|yuyv) --shm\n");
  std::exit(2);
}

}  // namespace

int main(int argc, char **argv) {
  if (argc < 2) usage();
  std::string cmd = argv[1];
  Args a = parse(argc, argv, 2);
  if (cmd == "colors") return cmd_colors(a);
  if (cmd == "train") return cmd_train(a);
  if (cmd == "render") return cmd_render(a);
  if (cmd == "frame") return cmd_frame(a);
  usage();
}
