/* imageproc: the colour lookup-table vision pipeline (libhrpimg.so).
 *
 *   YUYV frame --img_label_yuyv--> label image (one byte per pixel, a bit per colour class)
 *              --img_block_or----> block image (bit-OR of bs x bs blocks)
 *   label/block image --img_regions--> connected regions of a colour (bbox, centroid, area, moments)
 *   label image + rectangle --img_color_stats--> statistics of one colour in a region
 *
 * The lookup table (LUT) has 2^18 entries indexed by the top 6 bits of Y, U and V:
 *   index = (Y >> 2) << 12 | (U >> 2) << 6 | (V >> 2)
 * Each entry is a label: a bit mask of colour classes (bit 0 ball orange, ... as the config says).
 *
 * Images are plain row-major byte arrays owned by the caller; nothing here allocates on the
 * per-frame path except img_cc_new. Functions return 0 (or a count) on success and a negative
 * code on failure, with a message in the caller's buffer where one is taken. No exit().
 */
#ifndef HRP_IMAGEPROC_H
#define HRP_IMAGEPROC_H

#include <stddef.h>
#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

/* ---------------------------------------------------------------- lookup table */

#define IMG_LUT_SIZE 262144                 /* 2^18 entries, one byte each */
#define IMG_LUT_MAGIC "HRPLUT1"             /* 8 bytes with the NUL */

/* Index of a YUV triple in the LUT. */
static inline uint32_t img_lut_index(uint8_t y, uint8_t u, uint8_t v) {
  return ((uint32_t)(y >> 2) << 12) | ((uint32_t)(u >> 2) << 6) | (uint32_t)(v >> 2);
}

/* LUT file: 8-byte magic, u32 entry count (= IMG_LUT_SIZE), u32 CRC-32 of the table,
 * then the table (IMG_LUT_SIZE bytes). Little-endian. Total 262160 bytes. */
enum {
  IMG_EIO = -1,        /* file cannot be opened, read or written */
  IMG_EFORMAT = -2,    /* wrong size, magic, count or checksum */
  IMG_EARG = -3        /* invalid argument */
};

/* Reads a LUT file into lut (IMG_LUT_SIZE bytes). Errors name the file and what is wrong. */
int img_lut_load(const char *path, uint8_t *lut, char *err, size_t errlen);
/* Writes lut to path (through a temporary file and rename). */
int img_lut_save(const char *path, const uint8_t *lut, char *err, size_t errlen);
/* CRC-32 (IEEE) of n bytes. */
uint32_t img_crc32(const uint8_t *data, size_t n);

/* A colour class as a box in YUV space (inclusive bounds, 0..255). */
typedef struct img_color_range {
  uint8_t bit;                 /* label bit mask to OR into matching entries */
  uint8_t ymin, ymax, umin, umax, vmin, vmax;
} img_color_range;

/* ORs each range's bit into every LUT entry whose cell (4 x 4 x 4 YUV values) overlaps the
 * range. Does not clear lut first. Returns 0 or IMG_EARG. */
int img_lut_add_ranges(uint8_t *lut, const img_color_range *ranges, int nranges);

/* ---------------------------------------------------------------- labelling */

/* Labels a YUYV frame (width x height pixels, width even, 2 bytes per pixel) subsampled by
 * `scale` (2 or 4, ...: any even number): the output is (width/scale) x (height/scale); output
 * pixel (i, j) is the LUT entry of Y0, U, V of the YUYV pair holding source pixel
 * (i*scale, j*scale). Returns 0 or IMG_EARG. */
int img_label_yuyv(const uint8_t *yuyv, int width, int height, const uint8_t *lut, int scale,
                   uint8_t *labels);

/* Block image: out (ceil(w/bs) x ceil(h/bs)) = bit-OR of the labels of each bs x bs block. */
int img_block_or(const uint8_t *labels, int w, int h, int bs, uint8_t *out);

/* Counts the pixels whose label has any bit of mask. */
int img_count(const uint8_t *labels, int w, int h, uint8_t mask);

/* ---------------------------------------------------------------- regions */

/* A connected region or the statistics of a colour (pixel units of the image analysed). */
typedef struct img_region {
  int32_t area;                     /* pixels */
  int32_t xmin, xmax, ymin, ymax;   /* px, inclusive bounding box */
  double cx, cy;                    /* px, centroid */
  double cxx, cyy, cxy;             /* px^2, central second moments divided by area */
  double axis_major, axis_minor;    /* px, full lengths of the equivalent ellipse's axes */
  double orientation;               /* rad, of the major axis from the x axis (image y down) */
} img_region;

/* Workspace for connected regions of images up to max_w x max_h (allocated once). */
typedef struct img_cc img_cc;
img_cc *img_cc_new(int max_w, int max_h);
void img_cc_free(img_cc *cc);

/* Connected regions (8-connectivity) of the pixels whose label has any bit of mask.
 * Writes the largest min(found, maxn) regions, largest first, into out and returns the
 * number of regions found (may exceed maxn), or IMG_EARG. */
int img_regions(img_cc *cc, const uint8_t *labels, int w, int h, uint8_t mask,
                img_region *out, int maxn);

/* Statistics of the pixels with any bit of mask inside the inclusive rectangle
 * [x0, x1] x [y0, y1] (clipped to the image). area 0 if there are none. */
int img_color_stats(const uint8_t *labels, int w, int h, uint8_t mask,
                    int x0, int x1, int y0, int y1, img_region *out);

#ifdef __cplusplus
}
#endif
#endif
