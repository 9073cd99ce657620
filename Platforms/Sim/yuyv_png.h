// yuyv_png: writes a YUYV image to a PNG file (BT.601 full range), for the sim's tools and tests.
#ifndef HRP_SIM_YUYV_PNG_H
#define HRP_SIM_YUYV_PNG_H

#include <png.h>

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <string>
#include <vector>

namespace sim {

// 0, or -1 with a message naming the file.
inline int yuyv_write_png(const std::string &path, const uint8_t *yuyv, int w, int h, std::string *err) {
  FILE *f = fopen(path.c_str(), "wb");
  if (!f) {
    *err = path + ": cannot write";
    return -1;
  }
  png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, nullptr, nullptr, nullptr);
  png_infop info = png_create_info_struct(png);
  if (setjmp(png_jmpbuf(png))) {
    png_destroy_write_struct(&png, &info);
    fclose(f);
    *err = path + ": PNG encoding failed";
    return -1;
  }
  png_init_io(png, f);
  png_set_IHDR(png, info, w, h, 8, PNG_COLOR_TYPE_RGB, PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_DEFAULT,
               PNG_FILTER_TYPE_DEFAULT);
  png_write_info(png, info);
  std::vector<uint8_t> row(w * 3);
  auto clamp = [](double x) { return (uint8_t)std::min(255.0, std::max(0.0, x + 0.5)); };
  for (int v = 0; v < h; v++) {
    const uint8_t *src = yuyv + (size_t)v * w * 2;
    for (int u = 0; u < w; u++) {
      const double Y = src[2 * u], U = src[4 * (u / 2) + 1] - 128.0, V = src[4 * (u / 2) + 3] - 128.0;
      row[3 * u] = clamp(Y + 1.402 * V);
      row[3 * u + 1] = clamp(Y - 0.344136 * U - 0.714136 * V);
      row[3 * u + 2] = clamp(Y + 1.772 * U);
    }
    png_write_row(png, row.data());
  }
  png_write_end(png, nullptr);
  png_destroy_write_struct(&png, &info);
  fclose(f);
  return 0;
}

}  // namespace sim
#endif
