/* tests/test_spot.c - spot lights in shadowkit.h: the map's eye space and
   window (sk_spot_view, sk_spot_window), its matrix (sk_spot_matrix) and
   cone-versus-box culling (sk_spot_box_visible).

   Oracles, in double precision, written here:
     - the window: points sampled in the box (and its corners) beyond the
       near plane and inside the cone, projected by hand through the eye
       basis; every one must fall inside the window; and a box whose
       projection is known in closed form (a plate centred under a spot
       looking straight down) gives its exact rectangle;
     - the view fit: points sampled in box, view frustum and cone inside
       the window by the margin; the snapped window's side 2 tan a / 2^k
       and its corner on the texel grid, moving by whole texels with the
       view;
     - the matrix: the projected window corners at two depths land on the
       clip square's corners, window depth as Eq. 5.4.6 of King and Newhall
       2004 (z = zf/(zf-zn) - zf zn/((zf-zn) MA));
     - culling: points sampled in the box; one inside the cone (angle and
       range) means the box must be kept. */
#define SHADOWKIT_IMPLEMENTATION
#include "shadowkit.h"
#include "tests/sk_test.h"
#include <stdlib.h>
#include <math.h>

#define PI_D 3.14159265358979323846

static unsigned rng_state = 12345u;
static double rnd(void) {
    rng_state = rng_state * 1664525u + 1013904223u;
    return (double)(rng_state >> 8) / 16777216.0;
}
static sk_vec3 v3(float x, float y, float z) { sk_vec3 r; r.x = x; r.y = y; r.z = z; return r; }
static sk_aabb box(float x0, float y0, float z0, float x1, float y1, float z1) {
    sk_aabb b; b.min = v3(x0, y0, z0); b.max = v3(x1, y1, z1); return b;
}
/* eye-space coordinates of p (the view's rows), depth along the axis */
static void eye_of(const sk_mat4 *v, double px, double py, double pz, double e[3]) {
    int k;
    for (k = 0; k < 3; k++) e[k] = v->m[k] * px + v->m[4 + k] * py + v->m[8 + k] * pz + v->m[12 + k];
    e[2] = -e[2];
}

static void test_view_basis(void) {
    sk_vec3 apex = v3(1, 2, 3), axis = v3(0.3f, -1, 0.2f);
    sk_mat4 v = sk_spot_view(apex, axis);
    double e[3], al = sqrt(0.09 + 1 + 0.04);
    /* a point along the axis: on the eye's -z at its distance, x = y = 0 */
    eye_of(&v, 1 + 2 * 0.3 / al, 2 - 2 / al, 3 + 2 * 0.2 / al, e);
    SK_CHECK_NEAR(e[0], 0, 1e-5);
    SK_CHECK_NEAR(e[1], 0, 1e-5);
    SK_CHECK_NEAR(e[2], 2, 1e-5);
    /* rows orthonormal */
    SK_CHECK_NEAR(v.m[0] * v.m[0] + v.m[4] * v.m[4] + v.m[8] * v.m[8], 1, 1e-6);
    SK_CHECK_NEAR(v.m[0] * v.m[1] + v.m[4] * v.m[5] + v.m[8] * v.m[9], 0, 1e-6);
    /* bad input: the identity */
    v = sk_spot_view(apex, v3(0, 0, 0));
    SK_CHECK(v.m[0] == 1 && v.m[5] == 1 && v.m[12] == 0);
}

static void test_window_closed_form(void) {
    /* spot 3 above the ground, straight down, 60 degrees: a box x, z in
       [-1, 1], y in [0, 1] is seen at most 1 / 2 off the axis (its top
       corners, depth 2) */
    sk_aabb b = box(-1, 0, -1, 1, 1, 1);
    float w[4];
    int r = sk_spot_window(v3(0, 3, 0), v3(0, -1, 0), (float)(60 * PI_D / 180), 0.05f, &b, NULL, 0, 0, w);
    SK_CHECK(r == 1);
    SK_CHECK_NEAR(w[0], -0.5, 1e-6);
    SK_CHECK_NEAR(w[1], -0.5, 1e-6);
    SK_CHECK_NEAR(w[2], 0.5, 1e-6);
    SK_CHECK_NEAR(w[3], 0.5, 1e-6);
    /* a narrow cone inside the box's rectangle: the cone's own square */
    r = sk_spot_window(v3(0, 3, 0), v3(0, -1, 0), (float)(20 * PI_D / 180), 0.05f, &b, NULL, 0, 0, w);
    SK_CHECK(r == 1);
    SK_CHECK_NEAR(w[2], tan(20 * PI_D / 180), 1e-6);
    SK_CHECK_NEAR(w[0], -tan(20 * PI_D / 180), 1e-6);
    /* a box wholly behind the apex: nothing to render */
    b = box(-1, 4, -1, 1, 5, 1);
    SK_CHECK(sk_spot_window(v3(0, 3, 0), v3(0, -1, 0), 0.5f, 0.05f, &b, NULL, 0, 0, w) == 0);
    /* beside the cone */
    b = box(10, 0, -1, 12, 1, 1);
    SK_CHECK(sk_spot_window(v3(0, 3, 0), v3(0, -1, 0), 0.5f, 0.05f, &b, NULL, 0, 0, w) == 0);
    /* bad input */
    SK_CHECK(sk_spot_window(v3(0, 3, 0), v3(0, 0, 0), 0.5f, 0.05f, NULL, NULL, 0, 0, w) == -1);
    SK_CHECK(sk_spot_window(v3(0, 3, 0), v3(0, -1, 0), 2.0f, 0.05f, NULL, NULL, 0, 0, w) == -1);
    SK_CHECK(sk_spot_window(v3(0, 3, 0), v3(0, -1, 0), 0.5f, 0.0f, NULL, NULL, 0, 0, w) == -1);
    SK_CHECK(w[0] == 0 && w[2] == 0);
}

/* random spots and boxes, some straddling the near plane: every sampled
   point of the box in front of zn and inside the cone lies in the window */
static void test_window_covers(void) {
    int trial, outside = 0, samples = 0, clipped = 0;
    for (trial = 0; trial < 400; trial++) {
        sk_vec3 apex = v3((float)(rnd() * 8 - 4), (float)(rnd() * 4), (float)(rnd() * 8 - 4));
        sk_vec3 axis = v3((float)(rnd() * 2 - 1), (float)(rnd() * 2 - 1.5), (float)(rnd() * 2 - 1));
        float ha = (float)(0.1 + rnd() * 1.2), zn = 0.05f, w[4];
        double cx = rnd() * 8 - 4, cy = rnd() * 3, cz = rnd() * 8 - 4, t = tan(ha);
        sk_aabb b = box((float)(cx - rnd() * 3), (float)(cy - rnd() * 2), (float)(cz - rnd() * 3),
                        (float)(cx + rnd() * 3), (float)(cy + rnd() * 2), (float)(cz + rnd() * 3));
        sk_mat4 v = sk_spot_view(apex, axis);
        int r = sk_spot_window(apex, axis, ha, zn, &b, NULL, 0, 0, w), s;
        if (r != 1) continue;
        SK_CHECK_NEAR(w[2] - w[0], w[3] - w[1], 1e-5);
        SK_CHECK(w[0] >= -t - 1e-5 && w[2] <= t + 1e-5 && w[1] >= -t - 1e-5 && w[3] <= t + 1e-5);
        if (w[2] - w[0] < 2 * t - 1e-4) clipped++;
        for (s = 0; s < 400; s++) {
            double e[3], x, y;
            double px = b.min.x + (b.max.x - b.min.x) * (s < 8 ? (s & 1) : rnd());
            double py = b.min.y + (b.max.y - b.min.y) * (s < 8 ? (s >> 1 & 1) : rnd());
            double pz = b.min.z + (b.max.z - b.min.z) * (s < 8 ? (s >> 2 & 1) : rnd());
            eye_of(&v, px, py, pz, e);
            if (e[2] < zn) continue;
            x = e[0] / e[2]; y = e[1] / e[2];
            if (fabs(x) > t || fabs(y) > t) continue;
            samples++;
            if (x < w[0] - 1e-5 || x > w[2] + 1e-5 || y < w[1] - 1e-5 || y > w[3] + 1e-5) outside++;
        }
    }
    printf("window: %d samples in cone and box, %d outside the window; %d windows clipped by the box\n", samples,
           outside, clipped);
    SK_CHECK(samples > 10000);
    SK_CHECK(outside == 0);
    SK_CHECK(clipped > 20);
}

/* fitted to what random views see, snapped for a 256-texel map with a
   2-texel margin: every sampled point of box, view and cone (beyond zn)
   lies inside the window by the margin; the side is 2 tan a / 2^k and the
   corner on its texel grid from the cone's corner; a view moved a little
   keeps the side and moves the corner by whole texels */
static void test_window_view_snapped(void) {
    int trial, outside = 0, samples = 0, narrower = 0, grid_off = 0, tried = 0, side_kept = 0;
    const int res = 256;
    const float margin = 2.0f;
    for (trial = 0; trial < 300; trial++) {
        sk_vec3 apex = v3((float)(rnd() * 8 - 4), (float)(2 + rnd() * 3), (float)(rnd() * 8 - 4));
        sk_vec3 axis = v3((float)(rnd() * 2 - 1), (float)(-0.3 - rnd()), (float)(rnd() * 2 - 1));
        sk_vec3 eye = v3((float)(rnd() * 10 - 5), (float)(0.5 + rnd() * 4), (float)(rnd() * 10 - 5));
        sk_vec3 at = v3((float)(rnd() * 6 - 3), 0.0f, (float)(rnd() * 6 - 3)), eye2;
        float ha = (float)(0.3 + rnd() * 0.9), zn = 0.05f, w[4], w2[4], wb[4];
        double t = tan(ha), tex, k2;
        sk_aabb b = box(-6, 0, -6, 6, 2, 6);
        sk_mat4 v = sk_spot_view(apex, axis);
        sk_frustum f = sk_frustum_from_matrix(sk_mat4_mul(sk_mat4_perspective(0.4f, 1.6f, 0.1f, 5.0f),
                                                          sk_mat4_look_at(eye, at, v3(0, 1, 0))));
        sk_frustum f2;
        sk_vec3 verts[SK_CLIP_MAX_POINTS];
        int nv;
        int r = sk_spot_window(apex, axis, ha, zn, &b, &f, res, margin, w), s;
        if (r != 1) continue;
        tried++;
        tex = (w[2] - w[0]) / res;
        SK_CHECK_NEAR(w[2] - w[0], w[3] - w[1], 1e-5);
        k2 = log2(2 * t / (w[2] - w[0]));
        if (fabs(k2 - floor(k2 + 0.5)) > 1e-4) grid_off++;
        if (fabs((w[0] + t) / tex - floor((w[0] + t) / tex + 0.5)) > 1e-2 ||
            fabs((w[1] + t) / tex - floor((w[1] + t) / tex + 0.5)) > 1e-2)
            grid_off++;
        SK_CHECK(sk_spot_window(apex, axis, ha, zn, &b, NULL, res, margin, wb) == 1);
        if (w[2] - w[0] < wb[2] - wb[0] - 1e-6) narrower++;
        nv = sk_clip_frustum_aabb(&f, b, verts, SK_CLIP_MAX_POINTS);
        for (s = 0; s < 3000 + nv; s++) {
            double e[3], x, y;
            sk_vec3 q = v3((float)(b.min.x + (b.max.x - b.min.x) * rnd()), (float)(b.min.y + (b.max.y - b.min.y) * rnd()),
                           (float)(b.min.z + (b.max.z - b.min.z) * rnd()));
            int in = 1, k;
            /* the body's own vertices too (sk_clip_frustum_aabb, tests/test_core.c's), where the margin is tight */
            if (s >= 3000) q = verts[s - 3000];
            for (k = 0; k < 6 && in && s < 3000; k++)
                in = f.planes[k].n.x * q.x + f.planes[k].n.y * q.y + f.planes[k].n.z * q.z + f.planes[k].d >= 0;
            if (!in) continue;
            eye_of(&v, q.x, q.y, q.z, e);
            if (e[2] < zn) continue;
            x = e[0] / e[2]; y = e[1] / e[2];
            if (fabs(x) > t || fabs(y) > t) continue;
            samples++;
            /* inside by the margin, unless the cone's edge is nearer */
            if (x < w[0] + (w[0] > -t + 1e-6 ? margin * tex : 0) - 1e-5 ||
                x > w[2] - (w[2] < t - 1e-6 ? margin * tex : 0) + 1e-5 ||
                y < w[1] + (w[1] > -t + 1e-6 ? margin * tex : 0) - 1e-5 ||
                y > w[3] - (w[3] < t - 1e-6 ? margin * tex : 0) + 1e-5)
                outside++;
        }
        /* the view moved by a millimetre */
        eye2 = v3(eye.x + 0.001f, eye.y, eye.z - 0.001f);
        f2 = sk_frustum_from_matrix(sk_mat4_mul(sk_mat4_perspective(0.4f, 1.6f, 0.1f, 5.0f),
                                                sk_mat4_look_at(eye2, at, v3(0, 1, 0))));
        if (sk_spot_window(apex, axis, ha, zn, &b, &f2, res, margin, w2) == 1 &&
            fabs((w2[2] - w2[0]) - (w[2] - w[0])) < 1e-6) {
            side_kept++;
            SK_CHECK_NEAR((w2[0] - w[0]) / tex, floor((w2[0] - w[0]) / tex + 0.5), 1e-2);
        }
    }
    printf("view fit: %d windows, %d narrower than the scene's, %d off the grid; %d samples, %d outside; a view "
           "moved 1 mm kept the side %d times\n", tried, narrower, grid_off, samples, outside, side_kept);
    /* measured: 189 windows, 81 narrower, 8235 samples, the side kept 189 times;
       the margin left out of the snapped corner: 86 samples outside; the
       corner left off the grid: 44 windows off it */
    SK_CHECK(tried > 100);
    SK_CHECK(narrower > tried / 4);
    SK_CHECK(grid_off == 0);
    SK_CHECK(samples > 5000);
    SK_CHECK(outside == 0);
    SK_CHECK(side_kept > tried * 9 / 10);
}

static void test_matrix(void) {
    sk_vec3 apex = v3(0.5f, 4, -1), axis = v3(0.2f, -1, 0.1f);
    float w[4] = {-0.3f, -0.1f, 0.5f, 0.7f}, scale, bias;
    sk_mat4 m = sk_spot_matrix(apex, axis, w, 0.1f, 20.0f), v = sk_spot_view(apex, axis);
    int i;
    sk_vsdct_depth_coeffs(0.1f, 20.0f, &scale, &bias);
    for (i = 0; i < 8; i++) {
        /* the window corner (x, y) at depth d, back to world through the view's rows */
        double d = (i & 4) ? 7.0 : 1.5, x = ((i & 1) ? w[2] : w[0]) * d, y = ((i & 2) ? w[3] : w[1]) * d;
        double wp[3], c[4], ez = -d;
        int k;
        for (k = 0; k < 3; k++)
            wp[k] = v.m[4 * k + 0] * (x - v.m[12]) + v.m[4 * k + 1] * (y - v.m[13]) + v.m[4 * k + 2] * (ez - v.m[14]);
        for (k = 0; k < 4; k++) c[k] = m.m[k] * wp[0] + m.m[4 + k] * wp[1] + m.m[8 + k] * wp[2] + m.m[12 + k];
        SK_CHECK_NEAR(c[0] / c[3], (i & 1) ? 1 : -1, 1e-4);
        SK_CHECK_NEAR(c[1] / c[3], (i & 2) ? 1 : -1, 1e-4);
        SK_CHECK_NEAR(0.5 * c[2] / c[3] + 0.5, scale / d + bias, 1e-5);
    }
    m = sk_spot_matrix(apex, axis, w, 0.1f, 0.1f);
    SK_CHECK(m.m[0] == 1 && m.m[11] == 0);
}

static void test_box_visible(void) {
    int trial, kept = 0, culled = 0, wrong = 0;
    for (trial = 0; trial < 4000; trial++) {
        sk_vec3 apex = v3(0, 0, 0), axis = v3((float)(rnd() * 2 - 1), (float)(rnd() * 2 - 1), (float)(rnd() * 2 - 1));
        float ha = (float)(0.1 + rnd() * 1.3), range = (float)(2 + rnd() * 6);
        double cx = rnd() * 16 - 8, cy = rnd() * 16 - 8, cz = rnd() * 16 - 8, al, ca = cos(ha);
        sk_aabb b = box((float)cx, (float)cy, (float)cz, (float)(cx + rnd() * 2), (float)(cy + rnd() * 2),
                        (float)(cz + rnd() * 2));
        int vis = sk_spot_box_visible(apex, axis, ha, range, b), s, hit = 0;
        al = sqrt((double)axis.x * axis.x + (double)axis.y * axis.y + (double)axis.z * axis.z);
        if (al < 1e-3) continue;
        for (s = 0; s < 300 && !hit; s++) {
            double px = b.min.x + (b.max.x - b.min.x) * (s < 8 ? (s & 1) : rnd());
            double py = b.min.y + (b.max.y - b.min.y) * (s < 8 ? (s >> 1 & 1) : rnd());
            double pz = b.min.z + (b.max.z - b.min.z) * (s < 8 ? (s >> 2 & 1) : rnd());
            double d = sqrt(px * px + py * py + pz * pz);
            if (d > 0 && d <= range && (px * axis.x + py * axis.y + pz * axis.z) / (al * d) >= ca) hit = 1;
        }
        if (hit && !vis) wrong++;
        if (vis) kept++; else culled++;
    }
    printf("cone culling: %d kept, %d culled, %d culled wrongly\n", kept, culled, wrong);
    SK_CHECK(wrong == 0);
    SK_CHECK(culled > 1000);
    SK_CHECK(kept > 200);
    /* bad input keeps the box */
    SK_CHECK(sk_spot_box_visible(v3(0, 0, 0), v3(0, 0, 0), 0.5f, 5, box(10, 10, 10, 11, 11, 11)) == 1);
    /* a box straight down the axis, and one behind the apex */
    SK_CHECK(sk_spot_box_visible(v3(0, 3, 0), v3(0, -1, 0), 0.3f, 5, box(-0.1f, 0, -0.1f, 0.1f, 0.2f, 0.1f)) == 1);
    SK_CHECK(sk_spot_box_visible(v3(0, 3, 0), v3(0, -1, 0), 0.3f, 5, box(-0.1f, 4, -0.1f, 0.1f, 4.2f, 0.1f)) == 0);
}

SK_TEST_MAIN(test_view_basis, test_window_closed_form, test_window_covers, test_window_view_snapped, test_matrix,
             test_box_visible)
