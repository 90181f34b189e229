/* examples/image_io.h - image output for the tests, bench and example tracer.
   EXR through OpenEXR's C API (OpenEXRCore), PNG previews through libpng.
   These are the project's only image writers; nothing here is hand-encoded. */
#ifndef APPEAR_IMAGE_IO_H
#define APPEAR_IMAGE_IO_H
#ifdef __cplusplus
extern "C" {
#endif
/* Writes w x h pixels of nch float channels, interleaved per pixel, named by
   names[0..nch-1], ZIP-compressed scanline EXR. Returns 0 on success. */
int img_write_exr(const char *path, int w, int h, int nch, const char *const *names, const float *data);
/* Writes an 8-bit sRGB PNG preview of an interleaved RGB float image after
   multiplying by exposure (a power of two scale). Returns 0 on success. */
int img_write_png(const char *path, int w, int h, const float *rgb, float exposure);
#ifdef __cplusplus
}
#endif
#endif
