/* tests/test_debug_once.c - APPEAR_DEBUG's DEFAULT report (issue 30): each
 * report site (function + what was wrong) is printed once, its hits are
 * counted, and the counts come out on request (appear_debug_summary) and at
 * exit. This translation unit keeps the default APPEAR_DEBUG_REPORT and
 * points only its two hooks at the test: APPEAR_DEBUG_FILE (the stream, here
 * a temporary file read back) and APPEAR_ASSERT (here counted instead of
 * aborting), so the code under test is the default reporter itself.
 * (tests/test_debug.c defines its own APPEAR_DEBUG_REPORT, which gets every
 * call; the functions are static inline, so each file keeps its own setup.) */
#include <stdio.h>
#include <string.h>
static FILE *dbo_file; /* the default report's stream while the suite runs */
static int dbo_asserts;
#define APPEAR_DEBUG
#define APPEAR_DEBUG_FILE (dbo_file ? dbo_file : stderr)
#define APPEAR_ASSERT(x) ((void)((x) || ++dbo_asserts))
#include "harness.h"

/* What was written to f since the last read, *pos the offset read up to. */
static int dbo_read(FILE *f, long *pos, char *buf, int cap)
{
    int n;
    fflush(f);
    fseek(f, *pos, SEEK_SET);
    n = (int)fread(buf, 1, (size_t)(cap - 1), f);
    buf[n] = 0;
    *pos += n;
    fseek(f, 0, SEEK_END);
    return n;
}
static int dbo_lines(const char *s)
{
    int n = 0;
    for (; *s; ++s) n += *s == '\n';
    return n;
}
/* the count that a summary in s prints for "func: what", -1 if absent */
static long dbo_count(const char *s, const char *site)
{
    const char *b = strstr(s, site);
    long c = -1;
    if (!b) return -1;
    while (b > s && b[-1] != '\n') --b; /* the start of its line */
    return sscanf(b, "appear.h: %ld", &c) == 1 ? c : -1;
}

void suite_debug_once(void)
{
    appear_vec3 up = appear_vec3_make(0.0f, 0.0f, 1.0f), wi = appear_vec3_make(0.6f, 0.0f, 0.8f);
    appear_vec3 longv = appear_vec3_make(0.0f, 0.0f, 2.0f),
                nan3 = appear_vec3_make(NAN, 0.0f, 1.0f);
    static char buf[8192];
    FILE *sum;
    long at = 0, at_sum = 0; /* read up to, in dbo_file and sum */
    int i, n, bad = 0;

    dbo_file = tmpfile();
    sum = tmpfile();
    if (!dbo_file || !sum) {
        h_case("APPEAR_DEBUG default report: tmpfile() failed, not run");
        H_CHECK(0, "tmpfile() failed");
        return;
    }

    h_case("APPEAR_DEBUG default report: 1 site x 1000 calls -> 1 line, 1 assert, count 1000");
    {
        for (i = 0; i < 1000; ++i) bad += appear_isotropic_eval(up, longv) != 0.0f;
        n = dbo_read(dbo_file, &at, buf, (int)sizeof buf);
        H_CHECK(n > 0 && dbo_lines(buf) == 1 &&
                    strstr(buf, "appear.h: appear_isotropic_eval: wi is not unit length") == buf,
                "1000 bad calls printed %d lines: \"%s\"", dbo_lines(buf), buf);
        H_CHECK(dbo_asserts == 1, "APPEAR_ASSERT(0) after the first report only: %d calls",
                dbo_asserts);
        H_CHECK(bad == 0, "results changed: %d nonzero", bad);
        H_CHECK(appear__dbg_list_get()->at_exit == 1, "the summary is not registered with atexit");
        n = appear_debug_summary(sum);
        (void)dbo_read(sum, &at_sum, buf, (int)sizeof buf);
        H_CHECK(n == 1 && dbo_count(buf, "appear_isotropic_eval: wi is not unit length") == 1000,
                "summary of %d sites: \"%s\"", n, buf);
    }

    h_case(
        "APPEAR_DEBUG default report: each function + what is its own site; valid input is silent");
    {
        for (i = 0; i < 1000; ++i) (void)appear_isotropic_eval(up, wi);
        for (i = 0; i < 5; ++i) (void)appear_isotropic_eval(up, nan3);
        for (i = 0; i < 3; ++i) (void)appear_isotropic_pdf(up, longv);
        for (i = 0; i < 7; ++i) (void)appear_isotropic_eval(up, longv); /* the first site again */
        (void)dbo_read(dbo_file, &at, buf, (int)sizeof buf);
        H_CHECK(dbo_lines(buf) == 2 && strstr(buf, "appear_isotropic_eval: wi is NaN or Inf") &&
                    strstr(buf, "appear_isotropic_pdf: wi is not unit length"),
                "two new sites printed %d lines: \"%s\"", dbo_lines(buf), buf);
        H_CHECK(dbo_asserts == 3, "APPEAR_ASSERT(0) once per site: %d calls for 3 sites",
                dbo_asserts);
        n = appear_debug_summary(sum);
        (void)dbo_read(sum, &at_sum, buf, (int)sizeof buf);
        H_CHECK(n == 3 && dbo_count(buf, "appear_isotropic_eval: wi is not unit length") == 1007 &&
                    dbo_count(buf, "appear_isotropic_eval: wi is NaN or Inf") == 5 &&
                    dbo_count(buf, "appear_isotropic_pdf: wi is not unit length") == 3,
                "summary of %d sites: \"%s\"", n, buf);
        /* the atexit handler prints the same summary to APPEAR_DEBUG_FILE (at
           the real exit it writes into the temporary file, left open) */
        appear__dbg_at_exit();
        (void)dbo_read(dbo_file, &at, buf, (int)sizeof buf);
        H_CHECK(dbo_count(buf, "appear_isotropic_eval: wi is not unit length") == 1007 &&
                    strstr(buf, "APPEAR_DEBUG summary: 3 report sites") != NULL,
                "at-exit summary: \"%s\"", buf);
    }
    fclose(sum);
}
