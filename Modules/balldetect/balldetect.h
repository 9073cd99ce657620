/* balldetect: detection beside the colour table for today's field (libhrpbd.so).
 *
 *   label image --bd_field_boundary--> per column, the top row of the field (convex hull of green)
 *   label image + boundary + camera --bd_candidates--> spots where a ball of the expected size would
 *              be: non-field inside, field around (scored on an integral image of non-field pixels)
 *   YUYV frame + spot --bd_features--> a fixed-size patch description (normalised luma, chroma)
 *   features --bd_mlp_eval--> the classifier's probability that the spot is a ball
 *
 * Sizes: the label image is the frame subsampled by `scale` (imageproc's pipeline); positions given
 * to and returned from these functions are in full-resolution pixels (continuous coordinates:
 * (0, 0) is the top-left corner of the top-left pixel) unless a name says otherwise.
 * Nothing here allocates on the per-frame path except bd_new / bd_mlp_load. No exit().
 */
#ifndef HRP_BALLDETECT_H
#define HRP_BALLDETECT_H

#include <stddef.h>
#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

enum { BD_EIO = -1, BD_EFORMAT = -2, BD_EARG = -3 };

/* The camera at the frame: a pinhole with square pixels, pose in the level frame (z up). */
typedef struct bd_view {
  double f, cx, cy;          /* px: focal length and principal point (full resolution) */
  double R[9];               /* camera -> level frame, row-major; camera x optical axis, y left, z up */
  double height;             /* m, the camera above the ground */
  double blur[2];            /* px: how far the image moved during the exposure (a smear's length and
                                direction; 0, 0 for a still camera) */
} bd_view;

/* Apparent radius (px) of a ball of radius r (m) lying on the ground whose centre is seen at
 * (u, v); 0 if that ray does not go down to the plane of ball centres. */
double bd_ball_radius_px(const bd_view *view, double u, double v, double r);

/* Workspace for images up to max_w x max_h labels. */
typedef struct bd bd;
bd *bd_new(int max_w, int max_h);
void bd_free(bd *w);

/* The field boundary: top[x] (label rows, 0..h) for each label column x; rows >= top[x] are on the
 * field. Per column the first row starting a run of min_run rows that all hold a field label
 * (any bit of green); then the lower convex hull of those points (the field's image is convex, so
 * robots and balls standing in front of its edge are bridged). Columns outside the first and last
 * column with field get top = h. Returns the number of columns with field. */
int bd_field_boundary(bd *w, const uint8_t *labels, int wl, int hl, uint8_t green, int min_run, int16_t *top);

/* A ball candidate: centre and expected radius in full-resolution px, and its shape score. */
typedef struct bd_candidate {
  double u, v, radius;       /* px */
  double inner, ring;        /* fraction of non-field labels inside the disc and in a ring around it */
  double score;              /* inner - ring - the inner box's fraction beyond the boundary */
  double prob;               /* the classifier's probability (bd_candidates leaves it -1) */
} bd_candidate;

/* Ball candidates: label positions (every `step` labels) at most a ball's radius above the field
 * boundary where a disc of the ball's expected radius (from the view; ball_r in m) is mostly not
 * field (>= min_inner) and a ring around it mostly field or beyond the boundary (not-field labels
 * below the boundary <= max_ring); local maxima of inner - ring, the best first, none
 * within one radius of a better one; the centre refined to the centroid of the non-field labels in
 * its disc swept along the view's blur (the shape of a ball smeared by a moving camera: its centre
 * is then the smear's, the ball at the exposure's middle; the sweep beyond the field boundary left
 * out: the backdrop behind a ball at the field's edge), twice. `scale`: full-resolution px per label.
 * Writes up to maxn into out, returns the count. */
int bd_candidates(bd *w, const uint8_t *labels, int wl, int hl, int scale, uint8_t green,
                  const int16_t *top, const bd_view *view, double ball_r, int step, double min_inner,
                  double max_ring, double min_radius_px, bd_candidate *out, int maxn);

/* The centre of the candidate chosen as the ball (bd_candidates' arguments; top: the boundary) refined further: the
 * same centroid in the disc swept by the blur, up to 6 more times until it moves less than a quarter
 * label. Each pass halves its offset from a ball of the disc's size; two leave a quarter of it,
 * which for a near ball (its candidate may lie many labels off) is many pixels. Not for every
 * candidate: on a far ball's few labels the passes drift into what lies beside it, and the
 * classifier was trained on the centres of two; nor for a ball whose disc reaches beyond the field
 * boundary (the backdrop there is as not-field as the ball). Returns the passes made (0: left as it
 * was), BD_EARG for bad arguments. */
int bd_settle(const uint8_t *labels, int wl, int hl, int scale, uint8_t green, const int16_t *top, const bd_view *view,
              double ball_r, bd_candidate *c);

/* The chosen ball's centre from its outline (fit.c): rays from a start find where its region meets
 * the field (labels with the field's bits and no other; none counted that run past 1.5 radii into a
 * line touching the ball, out of the image or beyond the field boundary); the sphere's outline there
 * (its tangent cone for a centre on the plane of ball centres: the expected size at that distance,
 * swept along the view's blur, plus an offset loosely held to 0) fitted to those points with weights
 * that leave out the ones beyond it (a line's far edge); the rays cast again from its centre until it
 * stays. Tried from c's centre (settled) and from (u0, v0) (the centre before bd_settle, whose passes
 * may have climbed into a line touching the ball); a fit passes with at least a quarter of the rays
 * within 1.5 labels + 4% of the radius of its outline, no gap over half a turn between those, an
 * offset under a quarter of the radius, and the points holding the centre in every direction (the
 * eigenvalues of its covariance within 1:4); none where the ball's disc reaches beyond a field
 * boundary below the image's top row (as bd_settle). The passing fit with more such points moves c's centre (its
 * radius to the expected one there); returns their count, 0 when no fit passed (c left as it was; a
 * ball under 10 labels in radius is never fitted: there a smear the view's blur does not cover
 * misleads the fit more than a line the centroid), BD_EARG. */
int bd_fit(const uint8_t *labels, int wl, int hl, int scale, uint8_t green, const int16_t *top, const bd_view *view,
           double ball_r, double u0, double v0, bd_candidate *c);

/* Features of a square patch of side 2 * margin * radius around (u, v) in a YUYV frame:
 * BD_GRID x BD_GRID luma cells (mean over up to 3 x 3 samples each), normalised to zero mean and
 * unit spread, then BD_CGRID x BD_CGRID cells of U - 128 and of V - 128 over 32, then BD_NLEVEL
 * brightness levels that the normalisation removes: (mean - 128) / 64 of the whole patch and of its
 * middle half (where the ball is), and the spread over 64 (a white ball is brighter than a grey
 * robot's arm of the same shape). Samples outside the frame repeat its edge. Writes BD_NFEAT floats. */
#define BD_GRID 16
#define BD_CGRID 4
#define BD_NLEVEL 3
#define BD_NFEAT (BD_GRID * BD_GRID + 2 * BD_CGRID * BD_CGRID + BD_NLEVEL)
int bd_features(const uint8_t *yuyv, int width, int height, double u, double v, double radius,
                double margin, float *out);

/* An obstacle standing on the field (another robot): a band of label columns in each of which a
 * run of labels that are neither field nor line (not `field_mask`) rises from a foot on the field
 * up to the field boundary or beyond (robots stand out of the field; the ball, marks and lines lie
 * flat within it). Label units. */
typedef struct bd_obstacle {
  int32_t x0, x1;            /* columns, inclusive */
  int32_t top, foot;         /* highest row of the runs, the foot row (the 95th percentile of the columns' lowest rows) */
  int32_t foot_visible;      /* 0 when the runs go down to the image's bottom (the foot is below it) */
  int32_t red, blue;         /* labels of the team colours in the band */
  int32_t fx0, fx1;          /* columns of the non-field labels on the foot's rows (the feet), inclusive */
} bd_obstacle;

/* Obstacles in a label image with its field boundary (bd_field_boundary). min_run: rows a run
 * needs at least, min_below of them below the boundary; max_gap: field-mask labels bridged inside a run (lines seen through legs);
 * leg_gap: rows between a short run and the run above it that still make one (its foot is the
 * short run's: legs blurred into the field's colour above the feet); min_width: columns of a band,
 * and the columns without a run bridged inside one (the field seen between legs). A run's foot
 * must lie 2 rows below the boundary or more. Up to maxn bands, widest first; returns the count. */
int bd_obstacles(bd *w, const uint8_t *labels, int wl, int hl, const int16_t *top, uint8_t field_mask,
                 uint8_t red, uint8_t blue, int min_run, int min_below, int max_gap, int leg_gap,
                 int min_width, bd_obstacle *out, int maxn);

/* Labels in column x, rows y0..y1 (clipped to the image), with none of mask's bits; BD_EARG for a bad
 * column. */
int bd_column_count(const uint8_t *labels, int wl, int hl, int x, int y0, int y1, uint8_t mask);

/* A small classifier: nin inputs -> nhid ReLU units -> one sigmoid output. */
typedef struct bd_mlp bd_mlp;
/* Reads a model file: a line "hrp-ball-mlp 1 NIN NHID MARGIN", then W1 (NHID rows of NIN), b1
 * (NHID), w2 (NHID), b2 (1), whitespace-separated numbers. Errors name the file and the element. */
bd_mlp *bd_mlp_load(const char *path, char *err, size_t errlen);
void bd_mlp_free(bd_mlp *m);
int bd_mlp_nin(const bd_mlp *m);
double bd_mlp_margin(const bd_mlp *m);
/* The probability (0..1) for n = nin features. */
double bd_mlp_eval(const bd_mlp *m, const float *x);

#ifdef __cplusplus
}
#endif
#endif
