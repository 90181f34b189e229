/* tests/test_check.c - build/appear-check and tests/check.h: the command-line
   parser's errors, and the lossless / lossy figures through the same model
   factory and checks that the program runs. */
#define APPEAR_CHECK_NO_MAIN
#include "../examples/appear_check.c"
#include "harness.h"

static int parse_line(const char *line, ac_config *c, char *err, size_t en)
{
    static char buf[1024];
    char *argv[64], *tok, *save = 0;
    int argc = 0;
    snprintf(buf, sizeof buf, "appear-check %s", line);
    for (tok = strtok_r(buf, " ", &save); tok && argc < 63; tok = strtok_r(0, " ", &save)) argv[argc++] = tok;
    argv[argc] = 0;
    return ac_parse(argc, argv, c, err, en);
}

/* furnace of "SUBCOMMAND-less" model options at theta: returns albedo, se */
static int furnace_of(const char *line, double theta, long n, check_furnace_result *r)
{
    static ac_config c;
    ad_model m;
    char err[512];
    check_model cm;
    char full[512];
    snprintf(full, sizeof full, "furnace %s", line);
    if (parse_line(full, &c, err, sizeof err) || ac_make_model(&c, &m, err, sizeof err)) { h_fail("%s: %s", line, err); return -1; }
    cm = ad_check_model(&m);
    check_furnace(&cm, check_dir_theta_phi(theta, 0), n, 7, r);
    ac_free_model(&m);
    return 0;
}

void suite_check(void)
{
    static ac_config c;
    char err[512];
    int i;

    h_case("appear-check parser: bad input gives 2 and one line naming the option");
    {
        static const struct { const char *line, *needle; } bad[] = {
            { "furnace nosuchmodel", "nosuchmodel" },
            { "furnace conductor --alpha -1", "--alpha" },
            { "furnace conductor --alpha", "--alpha" },
            { "furnace conductor --bogus 1", "--bogus" },
            { "furnace conductor --eta abc", "--eta" },
            { "chi2 hg --g 1.5", "--g" },
            { "chi2 hg --alpha 0.3", "--alpha" },
            { "transmittance --kind nosuch", "--kind" },
            { "transmittance --samples 1.5", "--samples" },
            { "nosuchcommand hg", "nosuchcommand" },
            { "furnace", "missing model" },
            { "lobe ward --theta 30,x", "--theta" },
            { "furnace conductor-f0 --f0 1.5", "--f0" },
            { "furnace conductor-f0 --f0 -0.1", "--f0" },
            { "furnace conductor-f0 --f0 0.5,0.6", "--f0" },
            { "furnace conductor --f0 0.5 --eta 1", "--f0" },
            { "furnace dielectric --f0 0.5", "--f0" },
            { "transmittance --chromatic --channels 1,2", "--channels" },
            { "transmittance --chromatic --channels 1,-2,3", "--channels" },
            { "transmittance --chromatic --majorant nosuch", "--majorant" },
            { "transmittance --majorant common", "--majorant" },
            { "transmittance --chromatic --kind urm", "--kind" },
            { "transmittance --kind spectral", "--kind" },
            { "transmittance --free-flight --sigma-t 0", "--sigma-t" },
            { "transmittance --free-flight --sigma 1", "--sigma-t" }, /* the old name, with a hint */
            { "furnace eon --sigma 1.5", "--sigma" },
            { "furnace lambert --sigma 0.5", "--sigma" },
            { "furnace eon --eon-sampling best", "--eon-sampling" },
            { "transmittance --free-flight --length x", "--length" },
            { "transmittance --free-flight --d 1", "--length" },  /* the old name, with a hint */
            { "chi2 mie --d 10", "--diameter" },
            { "chi2 mie --length 1", "--length" },
            { "transmittance --free-flight --diameter 1", "--diameter" },
            { "transmittance --length 2", "--length" },
            { "transmittance --sigma-t 2", "--sigma-t" },
            { "transmittance --chromatic --free-flight", "--free-flight" } };
        for (i = 0; i < (int)(sizeof bad / sizeof bad[0]); ++i) {
            int r = parse_line(bad[i].line, &c, err, sizeof err);
            H_CHECK(r == 2 && strstr(err, bad[i].needle) && !strchr(err, '\n'), "'%s': returned %d, message '%s' (wants '%s')", bad[i].line, r,
                    r == 2 ? err : "", bad[i].needle);
        }
        H_CHECK(parse_line("furnace dielectric --dist ggx --alpha 0.3 --eta 1.5", &c, err, sizeof err) == 0 && c.alpha[0] == 0.3 && c.eta == 1.5,
                "good line rejected: %s", err);
        H_CHECK(parse_line("chi2 hg --help", &c, err, sizeof err) == 1 && c.cmd == C_CHI2 && c.model == AD_HG, "--help not seen");
    }

    h_case("appear-check options: one name, one meaning (--diameter: mie, --length: free flight, "
           "--sigma-t: free flight, --sigma: EON)");
    {
        int o, o2;
        ad_model m;
        /* the table may not give one name two entries: `--d` once meant the Mie diameter for
           the model subcommands and the segment length for transmittance */
        for (o = 0; o < O_COUNT; ++o)
            for (o2 = o + 1; o2 < O_COUNT; ++o2)
                H_CHECK(strcmp(ac_opts[o].name, ac_opts[o2].name) != 0,
                        "option --%s is listed twice (%s; %s)", ac_opts[o].name, ac_opts[o].help,
                        ac_opts[o2].help);
        H_CHECK(parse_line("chi2 mie --diameter 20", &c, err, sizeof err) == 0 &&
                    c.diameter == 20 && c.length == 1,
                "mie --diameter 20: %s (diameter %g)", err, c.diameter);
        H_CHECK(parse_line("transmittance --free-flight --sigma-t 2 --length 3", &c, err,
                           sizeof err) == 0 && c.length == 3 && c.sigma == 2 && c.free_flight,
                "--free-flight --length 3: %s (length %g)", err, c.length);
        H_CHECK(parse_line("furnace eon --sigma 1 --eon-sampling cosine", &c, err, sizeof err) == 0 &&
                    c.rough_sigma == 1 && c.eon_sampling == 1,
                "eon --sigma 1 --eon-sampling cosine: %s (sigma %g)", err, c.rough_sigma);
        if (parse_line("furnace mie --diameter 20", &c, err, sizeof err) ||
            ac_make_model(&c, &m, err, sizeof err))
            h_fail("mie --diameter 20: %s", err);
        else {
            appear_mie ref = appear_mie_make(20.0f);
            H_CHECK(m.ph.m.mie.g_hg == ref.g_hg && m.ph.m.mie.w_d == ref.w_d &&
                        m.ph.m.mie.draine.g == ref.draine.g && m.ph.m.mie.draine.alpha == ref.draine.alpha,
                    "mie --diameter 20 is not appear_mie_make(20): g_hg %g vs %g", m.ph.m.mie.g_hg,
                    ref.g_hg);
            ac_free_model(&m);
        }
    }

    h_case("appear-check --help: the program and every subcommand list each of their options with its default");
    {
        int cmd, o;
        (void)ac_run;
        for (cmd = -1; cmd < C_COUNT; ++cmd) {
            FILE *f = tmpfile();
            static char text[32768];
            size_t n;
            if (!f) { h_fail("tmpfile"); break; }
            ac_help(f, cmd, -1);
            rewind(f);
            n = fread(text, 1, sizeof text - 1, f);
            text[n] = 0;
            fclose(f);
            for (o = 0; o < O_COUNT; ++o) {
                char name[64];
                if (cmd >= 0 && !(ac_opts[o].cmds & CM(cmd))) continue;
                if (cmd == C_TRANSMITTANCE && ac_opts[o].model) continue;
                snprintf(name, sizeof name, "--%s ", ac_opts[o].name);
                H_CHECK(strstr(text, name) != NULL, "help of %s lacks %s", cmd < 0 ? "the program" : ac_cmd_name[cmd], name);
            }
            H_CHECK(strstr(text, "(default: ") != NULL, "help of %s shows no defaults", cmd < 0 ? "the program" : ac_cmd_name[cmd]);
        }
    }

    h_case("appear-check binary: exit code 2 on bad input (skipped when build/appear-check is not built)");
    {
        FILE *f = fopen("build/appear-check", "rb");
        if (f) {
            int r;
            fclose(f);
            r = system("./build/appear-check furnace conductor --alpha -1 >/dev/null 2>&1");
            H_CHECK(WIFEXITED(r) && WEXITSTATUS(r) == 2, "alpha -1: status %d", r);
            r = system("./build/appear-check furnace conductor --alpha >/dev/null 2>&1");
            H_CHECK(WIFEXITED(r) && WEXITSTATUS(r) == 2, "missing value: status %d", r);
            r = system("./build/appear-check furnace hg --theta 0 --samples 1000 >/dev/null 2>&1");
            H_CHECK(WIFEXITED(r) && WEXITSTATUS(r) == 0, "good run: status %d", r);
        }
    }

    h_case("appear-check furnace: lossless configurations are 1 within 4 standard errors");
    {
        static const char *const lossless[] = {
            "conductor-ms --dist ggx --alpha 1 --eta 0 --k 0",      /* F = 1: eta = k = 0 */
            "conductor-ms --dist beckmann --alpha 0.5 --eta 0 --k 0",
            "dielectric-ms --dist ggx --alpha 1 --eta 1.5",          /* R + e^2 T */
            "dielectric-ms --dist beckmann --alpha 0.5 --eta 1.33",
            "hg --g 0.9", "hg --g -0.5", "dhg", "rayleigh", "draine", "mie", "isotropic", "sggx-specular", "sggx-diffuse",
            "table --table examples/phase_table.txt", "thin-dielectric --eta 1.5", "dielectric --alpha 0 --eta 1.5" };
        static const double th[3] = { 0, 60, 85 };
        int t;
        for (i = 0; i < (int)(sizeof lossless / sizeof lossless[0]); ++i)
            for (t = 0; t < 3; ++t) {
                check_furnace_result r;
                if (furnace_of(lossless[i], th[t], strstr(lossless[i], "-ms") ? 4000 : 20000, &r)) continue;
                H_CHECK(fabs(r.albedo - 1) <= 4 * r.se + 2e-6, "%s theta %g: albedo %.6f +- %.6f", lossless[i], th[t], r.albedo, r.se);
            }
    }

    h_case("appear-check furnace: conductor-f0 with F0 = 1 equals conductor with eta = k = 0 (4 se)");
    {
        static const double th[3] = { 0, 60, 85 };
        for (i = 0; i < 3; ++i) {
            check_furnace_result a, b;
            if (furnace_of("conductor-f0 --alpha 0.5 --f0 1", th[i], 20000, &a)) continue;
            if (furnace_of("conductor --alpha 0.5 --eta 0 --k 0", th[i], 20000, &b)) continue;
            H_CHECK(fabs(a.albedo - b.albedo) <= 4 * sqrt(a.se * a.se + b.se * b.se) + 1e-6,
                    "theta %g: f0 %.6f +- %.6f, eta = k = 0 %.6f +- %.6f", th[i], a.albedo, a.se,
                    b.albedo, b.se);
        }
    }

    h_case("appear-check transmittance --chromatic: ratio, common majorant, every channel within 4 se");
    {
        ac_ctr_stats st;
        appear_majorant_segment seg[64];
        int ch;
        if (parse_line("transmittance --chromatic --kind ratio --profile cosine --channels 0.3,1,2 "
                       "--samples 20000", &c, err, sizeof err)) h_fail("parse: %s", err);
        else {
            ac_segments(c.profile, c.segments, c.tightness, seg);
            ac_run_ctracker(&c, APPEAR_TRACK_RATIO, seg, &st);
            for (ch = 0; ch < 3; ++ch) {
                double ex = exp(-c.channels[ch] * ac_prof_tau(c.profile, 1.0));
                H_CHECK(st.se[ch] > 0 && fabs(st.mean[ch] - ex) <= 4 * st.se[ch] && st.flags == 0,
                        "ch %d: %.6f +- %.2g vs %.6f (flags %lu)", ch, st.mean[ch], st.se[ch], ex,
                        st.flags);
            }
        }
    }

    h_case("appear-check furnace: single-scattering GGX conductor alpha 1, F = 1 matches the albedo table (tests/test_multiscatter.c)");
    {
        static const double mu[4] = { 1.0, 0.7, 0.4, 0.15 };
        for (i = 0; i < 4; ++i) {
            check_furnace_result r;
            double E = appear_conductor_albedo(APPEAR_GGX, 1.0f, (float)mu[i]);
            if (furnace_of("conductor --dist ggx --alpha 1 --eta 0 --k 0", acos(mu[i]) * 180 / 3.14159265358979, 40000, &r)) continue;
            /* the table's interpolation error is below 8e-3 relative (test_multiscatter.c) */
            H_CHECK(fabs(r.albedo - E) <= 4 * r.se + 8e-3 * E, "mu %g: furnace %.5f +- %.5f, table %.5f", mu[i], r.albedo, r.se, E);
            H_CHECK(r.albedo < 1 - 0.2, "mu %g: single scattering at alpha 1 must lose energy: %.5f", mu[i], r.albedo);
        }
    }

    h_case("appear-check chi2: every model at its default settings passes (p >= 0.01)");
    {
        for (i = 0; i < AD_COUNT; ++i) {
            char line[256];
            ad_model m;
            check_model cm;
            check_chi2_opts o;
            check_chi2_result r;
            check_vec3 wo;
            snprintf(line, sizeof line, "chi2 %s%s", ac_models[i].name, i == AD_TABLE ? " --table examples/phase_table.txt" : "");
            if (parse_line(line, &c, err, sizeof err) || ac_make_model(&c, &m, err, sizeof err)) { h_fail("%s: %s", line, err); continue; }
            if (m.approx_pdf || m.delta_only) { ac_free_model(&m); continue; } /* reported "not applicable" */
            cm = ad_check_model(&m);
            wo = ac_wo(&c, c.theta[0]);
            memset(&o, 0, sizeof o);
            o.n_z = c.n_z; o.n_phi = c.n_phi; o.n_samples = c.samples; o.seed = c.seed;
            o.axis = ac_chi2_axis(&c, &m, wo);
            if (check_chi2(&cm, wo, &o, &r)) h_fail("%s: chi2 did not run", line);
            else H_CHECK(r.p >= 0.01 && r.dof > 10, "%s: chi2 %.1f dof %d p %.3g (pdf mass %.5f)", m.name, r.chi2, r.dof, r.p, r.pdf_mass);
            check_chi2_free(&r);
            ac_free_model(&m);
        }
    }

    h_case("tests/check.h: reciprocity and consistency of the deterministic BSDFs");
    {
        static const char *const models[] = { "conductor --dist beckmann --alpha 0.1,0.4", "dielectric --alpha 0.3 --eta 1.5",
                                              "dielectric --alpha 0.2 --eta 0.7", "ward --variant balanced", "lambert", "fiber" };
        for (i = 0; i < (int)(sizeof models / sizeof models[0]); ++i) {
            char line[256];
            ad_model m;
            check_model cm;
            check_reciprocity_result rr;
            check_consistency_result cr;
            snprintf(line, sizeof line, "reciprocity %s", models[i]);
            if (parse_line(line, &c, err, sizeof err) || ac_make_model(&c, &m, err, sizeof err)) { h_fail("%s: %s", line, err); continue; }
            cm = ad_check_model(&m);
            check_reciprocity(&cm, 4000, 1e-4, 1, 3, &rr);
            H_CHECK(rr.compared > 500 && rr.max_rel < 1e-3, "%s: %ld compared, max violation %.3g (%.8g vs %.8g)", m.name, rr.compared, rr.max_rel,
                    rr.f_fwd, rr.f_rev);
            check_consistency(&cm, check_dir_theta_phi(50, 10), 4000, 1e-3, 5, &cr);
            H_CHECK(cr.checked > 1000 && cr.bad == 0, "%s: %ld of %ld samples disagree with eval/pdf (f %.3g pdf %.3g w %.3g)", m.name, cr.bad,
                    cr.checked, cr.max_rel_f, cr.max_rel_pdf, cr.max_rel_weight);
            ac_free_model(&m);
        }
    }
}
