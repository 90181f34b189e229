/* examples/image_io.c - see image_io.h */
#include "image_io.h"
#include <openexr.h>
#include <png.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

int img_write_exr(const char *path, int w, int h, int nch, const char *const *names, const float *data)
{
    exr_context_t ctx;
    exr_context_initializer_t init = EXR_DEFAULT_CONTEXT_INITIALIZER;
    exr_encode_pipeline_t enc;
    exr_chunk_info_t cinfo;
    int part = 0, lines = 1, y, c, first = 1, rv = 0;
    if (exr_start_write(&ctx, path, EXR_WRITE_FILE_DIRECTLY, &init) != EXR_ERR_SUCCESS) return -1;
    if (exr_add_part(ctx, "main", EXR_STORAGE_SCANLINE, &part) ||
        exr_initialize_required_attr_simple(ctx, part, w, h, EXR_COMPRESSION_ZIP)) { exr_finish(&ctx); return -1; }
    for (c = 0; c < nch; ++c)
        if (exr_add_channel(ctx, part, names[c], EXR_PIXEL_FLOAT, EXR_PERCEPTUALLY_LINEAR, 1, 1)) { exr_finish(&ctx); return -1; }
    if (exr_write_header(ctx) || exr_get_scanlines_per_chunk(ctx, part, &lines)) { exr_finish(&ctx); return -1; }
    memset(&enc, 0, sizeof enc);
    for (y = 0; y < h && rv == 0; y += lines) {
        if (exr_write_scanline_chunk_info(ctx, part, y, &cinfo)) { rv = -1; break; }
        if (first ? exr_encoding_initialize(ctx, part, &cinfo, &enc) : exr_encoding_update(ctx, part, &cinfo, &enc)) { rv = -1; break; }
        for (c = 0; c < enc.channel_count; ++c) {
            int k;
            for (k = 0; k < nch; ++k) if (strcmp(enc.channels[c].channel_name, names[k]) == 0) break;
            if (k == nch) { rv = -1; break; }
            enc.channels[c].encode_from_ptr = (const uint8_t *)(data + ((size_t)y * w * nch + k));
            enc.channels[c].user_pixel_stride = (int32_t)(nch * sizeof(float));
            enc.channels[c].user_line_stride = (int32_t)(w * nch * sizeof(float));
            enc.channels[c].user_data_type = EXR_PIXEL_FLOAT;
            enc.channels[c].user_bytes_per_element = (int16_t)sizeof(float);
        }
        if (rv) break;
        if (first && exr_encoding_choose_default_routines(ctx, part, &enc)) { rv = -1; break; }
        first = 0;
        if (exr_encoding_run(ctx, part, &enc)) rv = -1;
    }
    if (!first) exr_encoding_destroy(ctx, &enc);
    if (exr_finish(&ctx)) rv = -1;
    return rv;
}

static unsigned char to_srgb8(float v)
{
    float s;
    if (!(v > 0.0f)) return 0;
    if (v >= 1.0f) return 255;
    s = v <= 0.0031308f ? 12.92f * v : 1.055f * powf(v, 1.0f / 2.4f) - 0.055f;
    return (unsigned char)(s * 255.0f + 0.5f);
}

int img_write_png(const char *path, int w, int h, const float *rgb, float exposure)
{
    png_image img;
    unsigned char *buf = (unsigned char *)malloc((size_t)w * h * 3);
    size_t i;
    int ok;
    if (!buf) return -1;
    for (i = 0; i < (size_t)w * h * 3; ++i) buf[i] = to_srgb8(rgb[i] * exposure);
    memset(&img, 0, sizeof img);
    img.version = PNG_IMAGE_VERSION;
    img.width = (png_uint_32)w;
    img.height = (png_uint_32)h;
    img.format = PNG_FORMAT_RGB;
    ok = png_image_write_to_file(&img, path, 0, buf, 0, NULL);
    free(buf);
    return ok ? 0 : -1;
}
