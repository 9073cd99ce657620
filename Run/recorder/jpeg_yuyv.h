/* jpeg_yuyv: YUYV (BT.601 video range) frames into JPEG without a detour through BGR (jpeg_yuyv.c). */
#ifndef HRP_REC_JPEG_YUYV_H
#define HRP_REC_JPEG_YUYV_H

#include <stddef.h>
#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

typedef struct rec_jpeg rec_jpeg;
rec_jpeg *rec_jpeg_new(void);   /* NULL when out of memory */
void rec_jpeg_free(rec_jpeg *j);
/* Compresses a w x h YUYV frame (w even) at quality 0..100; *jpeg stays valid until the next call.
 * 0, or -1 with rec_jpeg_error() saying why. */
int rec_jpeg_encode(rec_jpeg *j, const uint8_t *yuyv, int w, int h, int quality, const uint8_t **jpeg, size_t *len);
const char *rec_jpeg_error(const rec_jpeg *j);
/* The planes the encoder compresses: Y (w x h, full range), U and V (w/2 x (h+1)/2, each line pair's
 * mean). simd 0: the plain table loop (the reference jpeg_yuyv_test compares the SIMD one with). */
void rec_jpeg_planes(const uint8_t *yuyv, int w, int h, uint8_t *Y, uint8_t *U, uint8_t *V, int simd);

#ifdef __cplusplus
}
#endif
#endif
