/* tb_image.h - PNG output for the testbed (stb_image_write).

   All inputs have row 0 at the BOTTOM (GL readback order); the writers flip
   so that row 0 ends up at the bottom of the PNG. Parent directories of the
   path are created (mkdir -p). Each writer returns 0 on success, -1 on
   failure.

   Linking: Debian's libstb-dev ships stb_image_write compiled in libstb.so
   (pkg-config stb, -lstb); build with -DTB_STB_IMPLEMENTATION to compile
   the implementation into tb_image.c instead (no -lstb then).

   Colours of the error image (class: lit when visibility >= 0.5):
     correct lit     light grey (200,200,200)   correct shadow dark grey (64,64,64)
     false lit       red        (230, 40, 40)   false shadow   blue      (40, 90,230)
     not covered     black      (0, 0, 0)       (reference < 0)
     invalid result  magenta    (255, 0,255)    (NaN or infinite on a covered pixel) */
#ifndef TB_IMAGE_H
#define TB_IMAGE_H

#ifdef __cplusplus
extern "C" {
#endif

/* rgb: 3*w*h bytes; rgba: 4*w*h bytes */
int tb_image_write_rgb8(const char *path, int w, int h, const unsigned char *rgb);
int tb_image_write_rgba8(const char *path, int w, int h, const unsigned char *rgba);
/* visibility [0,1] -> grey; negative (no receiver) -> dark blue (24,32,64);
   not finite -> magenta */
int tb_image_write_visibility(const char *path, int w, int h, const float *vis);
/* any scalar: (v - lo) / (hi - lo) clamped -> grey; not finite -> magenta */
int tb_image_write_gray(const char *path, int w, int h, const float *v, float lo, float hi);
/* reference vs result, colours above */
int tb_image_write_error(const char *path, int w, int h, const float *ref, const float *result);
/* mkdir -p of the directory part of path; 0 ok */
int tb_image_make_parent_dirs(const char *path);

#ifdef __cplusplus
}
#endif
#endif /* TB_IMAGE_H */
