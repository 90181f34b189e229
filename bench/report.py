#!/usr/bin/env python3
"""bench/report.py - joins what `make bench` measured into one report.

Reads (all under bench/out/, missing inputs are skipped):
  bench_<build>.csv       timed rows of each build (build,group,name,ns_per_call,max_err,note)
  callgrind_<build>.csv   the same rows run once under callgrind (build,group,name,seq,n)
  cg_<build>/cg.out.<k>   callgrind dumps; dump "bt <seq>" holds exactly one row's loop
  media.csv               transmittance estimators (bench_media.c)
Writes:
  report.md               every table below in Markdown (stdout gets the same in plain text)
  bench_all.csv           the joined table (one line per row, ns per build, Ir per call)
  plot_*.dat, plot_vars.gp  data for bench/plots.gp (plot_latency.dat: appear/baseline latency ratios)
Python 3 standard library only.
"""
import csv
import glob
import math
import os
import re
import sys

OUT = sys.argv[1] if len(sys.argv) > 1 else "bench/out"
TIMED = [("O2", "gcc -O2"), ("O3native", "gcc -O3 -march=native -fno-math-errno"),
         ("clang_O3native", "clang -O3 -march=native -fno-math-errno")]
COUNTED = [("O2", "gcc -O2"), ("O3", "gcc -O3 -fno-math-errno, no -march=native")]
FAST = "O3native"  # the build whose times the speed-against-error tables quote


def fnum(s):
    try:
        v = float(s)
    except (TypeError, ValueError):
        return None
    return v if math.isfinite(v) else None


def read_rows(path):
    if not os.path.exists(path):
        return []
    with open(path, newline="") as f:
        return list(csv.DictReader(f))


def keyed(rows):
    """(group, name, occurrence) keys in file order"""
    seen, out = {}, []
    for r in rows:
        k = (r["group"], r["name"])
        seen[k] = seen.get(k, 0) + 1
        out.append(((r["group"], r["name"], seen[k]), r))
    return out


# ---------------------------------------------------------------- join
table = {}   # key -> dict
order = []
for b, _ in TIMED:
    for k, r in keyed(read_rows(os.path.join(OUT, "bench_%s.csv" % b))):
        if k not in table:
            table[k] = {"group": k[0], "name": k[1], "ns": {}, "err": {}, "note": {}, "ir": {}}
            order.append(k)
        table[k]["ns"][b] = fnum(r["ns_per_call"])
        e = fnum(r["max_err"])
        table[k]["err"][b] = e if e is not None and e >= 0 else None
        table[k]["note"][b] = r.get("note", "")


def dump_ir(build):
    """seq -> total Ir of that b_time loop"""
    res = {}
    for path in glob.glob(os.path.join(OUT, "cg_%s" % build, "cg.out.*")):
        seq = ir = None
        with open(path, errors="replace") as f:
            for line in f:
                m = re.match(r"desc: Trigger: Client Request: bt (\d+)", line)
                if m:
                    seq = int(m.group(1))
                m = re.match(r"(?:totals|summary): (\d+)", line)
                if m:
                    ir = int(m.group(1))
        if seq is not None and ir is not None:
            res[seq] = ir
    return res


have_ir = []
for b, _ in COUNTED:
    irs = dump_ir(b)
    rows = read_rows(os.path.join(OUT, "callgrind_%s.csv" % b))
    if not irs or not rows:
        continue
    have_ir.append(b)
    for k, r in keyed(rows):
        seq, n = int(r["seq"]), int(r["n"])
        if k in table and seq in irs and n > 0:
            table[k]["ir"][b] = irs[seq] / n


def ns(row, b):
    return row["ns"].get(b)


def err(row):
    for b in (FAST, "O2", "clang_O3native"):
        if row["err"].get(b) is not None:
            return row["err"][b]
    return None


def note(row):
    for b in (FAST, "O2", "clang_O3native"):
        if row["note"].get(b):
            return row["note"][b]
    return ""


def f_ns(v):
    if v is None:
        return "-"
    return "%.2f" % v if v < 100 else "%.0f" % v


def f_e(v):
    return "-" if v is None else "%.1e" % v


def f_ir(v):
    return "-" if v is None else ("%.1f" % v if v < 100 else "%.0f" % v)


def f_mps(v):
    if v is None or v <= 0:
        return "-"
    m = 1e3 / v
    return "%.0f" % m if m >= 10 else "%.1f" % m


def best(row):
    vals = [ns(row, b) for b, _ in TIMED if ns(row, b)]
    return min(vals) if vals else None


# ---------------------------------------------------------------- output helpers
md = []
txt = []


def section(title, text=""):
    md.append("\n## %s\n" % title)
    txt.append("\n== %s" % title)
    if text:
        md.append(text + "\n")
        txt.append(text)


def emit(header, rows, align=None):
    if not rows:
        md.append("(no rows)\n")
        txt.append("(no rows)")
        return
    md.append("| " + " | ".join(header) + " |")
    md.append("|" + "|".join("---:" if (align and align[i] == "r") else "---" for i in range(len(header))) + "|")
    for r in rows:
        md.append("| " + " | ".join(str(c).replace("|", "/") for c in r) + " |")
    md.append("")
    w = [max(len(str(h)), max(len(str(r[i])) for r in rows)) for i, h in enumerate(header)]
    w[-1] = min(w[-1], 70)
    def line(cells):
        out = []
        for i, c in enumerate(cells):
            c = str(c)
            if i == len(cells) - 1:
                out.append(c[:70])
            elif align and align[i] == "r":
                out.append(c.rjust(w[i]))
            else:
                out.append(c.ljust(w[i]))
        return "  ".join(out).rstrip()
    txt.append(line(header))
    for r in rows:
        txt.append(line(r))


timed_builds = [b for b, _ in TIMED if any(b in table[k]["ns"] for k in order)]
md.append("# appear.h benchmark report\n")
md.append("Generated by `make bench` (bench/report.py). Builds timed: " +
          "; ".join("**%s** = %s" % (b, d) for b, d in TIMED if b in timed_builds) +
          ". ns per call = median of 9 runs over inputs drawn before timing (bench/bench.h). "
          "Ir = instructions per call counted by callgrind (valgrind 3.19 cannot run AVX-512, so counted on " +
          "; ".join("**%s** = %s" % (b, d) for b, d in COUNTED) + ") in quick mode. "
          "This machine is shared and noisy (20-50% run to run): compare rows of one build; differences under 25% are ties.\n")
if not have_ir:
    md.append("Instruction counts: none (valgrind or <valgrind/callgrind.h> missing).\n")

# ---------------------------------------------------------------- 1. throughput
section("Throughput: every public eval / pdf / sample and the baselines",
        "ns per call per build, M calls/s at the best build, Ir per call, O2/best = speed-up of the best optimised build over -O2 "
        "(large values: the loop vectorised with AVX-512), vec = Ir O2 / Ir O3 (>= 2: vectorised by gcc -O3 with SSE2 but not at -O2; gcc 12 already vectorises cheap loops at -O2, so no there can mean vectorised at both), max error against a double reference where the row measures it.")
hdr = ["group", "function"] + ["ns %s" % b for b in timed_builds] + ["M/s best", "O2/best"] + \
      ["Ir %s" % b for b in have_ir] + (["vec"] if len(have_ir) == 2 else []) + ["max err", "note"]


def vec(r):
    """Ir O2 / Ir O3: gcc -O3 without -march vectorises 4-wide (SSE2); a ratio >= 2 means the loop vectorised"""
    a, b = r["ir"].get("O2"), r["ir"].get("O3")
    if not a or not b:
        return ["-"]
    return ["yes %.1f" % (a / b) if a / b >= 2 else "no %.1f" % (a / b)]


LAT_GROUPS = ("latency", "latency_chain")  # bench/bench_latency.c: the pattern, its diagnostics
rows = []
for k in order:
    r = table[k]
    if r["group"] in LAT_GROUPS:
        continue  # their own tables below
    o2, bs = ns(r, "O2"), best(r)
    rows.append([r["group"], r["name"]] + [f_ns(ns(r, b)) for b in timed_builds] +
                [f_mps(bs), "%.1f" % (o2 / bs) if o2 and bs else "-"] +
                [f_ir(r["ir"].get(b)) for b in have_ir] + (vec(r) if len(have_ir) == 2 else []) + [f_e(err(r)), note(r)])
emit(hdr, rows, ["l", "l"] + ["r"] * (len(hdr) - 4) + ["l", "l"])

# ---------------------------------------------------------------- 2. speed vs error
BASE_RE = re.compile(r"baseline|libm|plain|textbook|listing|quadrature|exact|no compensation|Walter07", re.I)

section("Speed against error: special functions, ours vs libm",
        "Times at %s; max error against double over the stated range (relative; absolute for sincos and atan2). "
        "vec = time with auto-vectorisation disabled / time as built." % FAST)
rows = []
for k in order:
    r = table[k]
    if r["group"] != "special" or r["name"].endswith(" libm") or "disabled" in r["name"]:
        continue
    lib = table.get(("special", r["name"] + " libm", 1))
    nv = table.get(("special", r["name"] + ", auto-vectorisation disabled", 1))
    o, l = ns(r, FAST), ns(lib, FAST) if lib else None
    v = ns(nv, FAST) if nv else None
    rows.append([r["name"], f_ns(o), f_ns(l), "%.1fx" % (l / o) if o and l else "-", f_e(err(r)),
                 f_e(err(lib)) if lib else "-", "%.1f" % (v / o) if v and o else "-",
                 f_ir(r["ir"].get("O2")), f_ir(lib["ir"].get("O2")) if lib else "-"])
emit(["function", "ours ns", "libm ns", "speed-up", "ours err", "libm err", "vec", "Ir ours O2", "Ir libm O2"], rows,
     ["l", "r", "r", "r", "r", "r", "r", "r", "r"])

section("Speed against error: approximations and the plain baselines from the papers",
        "Each shortcut next to the reference it replaces, in one run (times at O2 and %s). err: see the note "
        "(max over the inputs, against double or the exact inverse CDF)." % FAST)
rows = []
for k in order:
    r = table[k]
    if r["group"] in ("special", "variance", "energy"):
        continue
    if r["group"] == "batch" and "Heitz" not in r["name"]:
        continue
    if err(r) is None and not BASE_RE.search(r["name"] + " " + note(r)):
        continue
    rows.append([r["group"], r["name"], f_ns(ns(r, "O2")), f_ns(ns(r, FAST)), f_e(err(r)), note(r)])
emit(["group", "function", "ns O2", "ns " + FAST, "max err", "note"], rows, ["l", "l", "r", "r", "r", "l"])

section("Speed against error: energy compensation (albedo scaling, Turquin 2019)",
        "err = max over cos theta_o of |1 - white-furnace albedo| of a lossless GGX conductor (F = 1): energy lost "
        "without compensation, residual (incl. Monte Carlo noise ~1e-3) with it.")
rows = [[r["name"], f_ns(ns(r, "O2")), f_ns(ns(r, FAST)), f_ir(r["ir"].get("O2")), f_e(err(r)), note(r)]
        for r in (table[k] for k in order) if r["group"] == "energy"]
emit(["function", "ns O2", "ns " + FAST, "Ir O2", "err", "note"], rows, ["l", "r", "r", "r", "r", "l"])

section("Speed against error: multiple scattering (single scattering, albedo-scaling compensation, Heitz 2016 random walk)",
        "Conductor with F = 1 (white furnace), times at O2 and %s; err = max over 16 cos theta_o of |E - 1| (single, "
        "compensated: double quadrature times the applied factor; walk: mean sample weight, exactly 1 per completed walk). "
        "Random-walk eval = one unbiased estimate (two walks). Plot: bench/out/ms_tradeoff.png." % FAST)
rows, seen_ms = [], {}
for k in order:
    r = table[k]
    if r["group"] != "ms tradeoff":
        continue
    base, _, kind = r["name"].rpartition(" ")
    seen_ms.setdefault(base, {})[kind] = r
for base, d in seen_ms.items():
    ev, sa = d.get("eval"), d.get("sample")
    parts = base.split(" ", 2)  # type, a=alpha, variant
    rows.append([parts[2] if len(parts) > 2 else base, parts[0], parts[1][2:] if len(parts) > 1 else "",
                 f_ns(ns(ev, "O2")) if ev else "-", f_ns(ns(ev, FAST)) if ev else "-",
                 f_ns(ns(sa, "O2")) if sa else "-", f_ns(ns(sa, FAST)) if sa else "-", f_e(err(ev or sa))])
emit(["variant", "type", "alpha", "ns eval O2", "ns eval " + FAST, "ns sample O2", "ns sample " + FAST, "max |E - 1|"], rows,
     ["l", "l", "r", "r", "r", "r", "r", "r"])

section("Estimators: variance of a reflected-radiance estimate per sampling strategy",
        "ns per estimate (sample + eval); variance and efficiency 1/(variance x ns) in the raw logs "
        "(bench/out/raw_<build>.txt).")
rows = [[r["name"], f_ns(ns(r, "O2")), f_ns(ns(r, FAST)), f_ns(ns(r, "clang_O3native"))]
        for r in (table[k] for k in order) if r["group"] == "variance"]
emit(["estimate", "ns O2", "ns " + FAST, "ns clang_O3native"], rows, ["l", "r", "r", "r"])

# ---------------------------------------------------------------- 3. media
media = read_rows(os.path.join(OUT, "media.csv"))
section("Transmittance estimators: efficiency against majorant tightness (Kettunen et al. 2021)",
        "Relative efficiency = 1/(MSE x density lookups), divided by that of ratio tracking, geometric mean over the 6 "
        "Georgiev et al. 2019 profiles (cases where an estimator is exact, ratio > 1e6, left out); "
        "tightness = max sigma / majorant. MSE, not variance: ray marching is biased. "
        "Full table: bench/out/media.csv (last build run).")
ests, tights, profs = [], [], []
for r in media:
    if r["estimator"] not in ests:
        ests.append(r["estimator"])
    if r["tightness"] not in tights:
        tights.append(r["tightness"])
    if r["profile"] not in profs:
        profs.append(r["profile"])


def eff_mse(r):
    """1 / (MSE x lookups): MSE, not variance, so that a biased or collapsing estimator pays for its bias"""
    m, lk = fnum(r["mse"]), fnum(r["lookups"])
    return 1.0 / (m * lk) if m and lk and m > 0 and lk > 0 else None


rel = {}  # (profile, tightness, estimator) -> efficiency / that of ratio tracking
for r in media:
    ref = [x for x in media if x["profile"] == r["profile"] and x["tightness"] == r["tightness"] and x["estimator"] == ests[0]]
    a, b = eff_mse(r), eff_mse(ref[0]) if ref else None
    rel[(r["profile"], r["tightness"], r["estimator"])] = a / b if a and b else None
rows = []
for e in ests:
    cells = [e]
    for t in tights:
        v = [rel.get((p, t, e)) for p in profs]
        v = [x for x in v if x is not None and 0 < x < 1e6]
        lk = [fnum(r["lookups"]) for r in media if r["estimator"] == e and r["tightness"] == t]
        lk = [x for x in lk if x is not None]
        g = math.exp(sum(math.log(x) for x in v) / len(v)) if v else None
        cells.append("-" if g is None else ("%.3g" % g))
        cells.append("%.1f" % (sum(lk) / len(lk)) if lk else "-")
    rows.append(cells)
hdr = ["estimator"]
for t in tights:
    hdr += ["rel eff @%s" % t, "lookups @%s" % t]
emit(hdr, rows, ["l"] + ["r"] * (len(hdr) - 1))

# ---------------------------------------------------------------- 4. batch
section("Batch (structure of arrays) vs scalar loop, ns per element",
        "Same inputs, same outputs (the note says whether every value is bit-identical); speed-up = scalar / batch.")
rows = []
batch_plot = []
for k in order:
    r = table[k]
    if r["group"] != "batch" or not r["name"].endswith(" batch"):
        continue
    base = r["name"][:-len(" batch")]
    s = table.get(("batch", base + " scalar", 1))
    if not s:
        continue
    cells = [base]
    for b in timed_builds:
        cells += [f_ns(ns(s, b)), f_ns(ns(r, b))]
    sp = ns(s, FAST) / ns(r, FAST) if ns(s, FAST) and ns(r, FAST) else None
    m = re.search(r"bit-identical: (\w+)", note(r))
    cells += ["%.1fx" % sp if sp else "-", f_ir(s["ir"].get("O2")), f_ir(r["ir"].get("O2")), f_e(err(r)),
              m.group(1) if m else "-"]
    rows.append(cells)
    batch_plot.append((base, [ns(s, b) for b in timed_builds], [ns(r, b) for b in timed_builds]))
hdr = ["function"]
for b in timed_builds:
    hdr += ["scalar %s" % b, "batch %s" % b]
hdr += ["speed-up " + FAST, "Ir scalar O2", "Ir batch O2", "max err", "identical"]
emit(hdr, rows, ["l"] + ["r"] * (len(hdr) - 2) + ["l"])
for k in order:
    r = table[k]
    if r["group"] == "batch" and "Heitz" in r["name"]:
        txt.append("  %s: %s" % (r["name"], note(r)))
        md.append("- %s: %s ns at %s. %s" % (r["name"], f_ns(ns(r, FAST)), FAST, note(r)))


# ---------------------------------------------------------------- 5. latency
# bench/bench_latency.c: rows "<name>" (appear; note "ratio=R ...") and
# "<name> [baseline]"; ratio = median over paired runs of appear / baseline
def lat_ratio(row, b):
    m = re.search(r"ratio=([0-9.]+)", row["note"].get(b, "") or "")
    return float(m.group(1)) if m else None


def median(v):
    v = sorted(v)
    n = len(v)
    return None if not n else (v[n // 2] if n % 2 else 0.5 * (v[n // 2 - 1] + v[n // 2]))


lat_builds = [b for b in timed_builds if any(table[k]["group"] == "latency" and b in table[k]["ns"] for k in order)]
section("Latency: one call at a time, each input depending on the previous output",
        "bench/bench_latency.c: every function behind a non-inlined wrapper in a dependent chain; the baseline "
        "(tests/listings.h: each a transcription of the peer's function named in the baseline column, its "
        "file named in listings.h) timed in alternation with appear's function; "
        "ratio = median of the per-pair ratios appear / baseline (> 1: appear is slower). check = max relative "
        "difference of the two on the same inputs (value, or pdf/f at the baseline's sample). "
        "Single timing: `./build/bench_O3native latency <substring>`.")
lat_pairs, lat_single = [], []
for k in order:
    r = table[k]
    if r["group"] != "latency" or r["name"].endswith(" [baseline]"):
        continue
    bl = table.get(("latency", r["name"] + " [baseline]", k[2]))
    (lat_pairs if bl else lat_single).append((r, bl))
def lat_cells(r, bl):
    """name, then ns / baseline ns / ratio per build; and the ratios"""
    cells, rat = [r["name"]], []
    for b in lat_builds:
        q_ = lat_ratio(r, b)
        rat.append(q_)
        cells += [f_ns(ns(r, b)), f_ns(ns(bl, b)) if bl else "-", "%.2f" % q_ if q_ is not None else "-"]
    return cells, rat


rows, plot_lat = [], []
for r, bl in lat_pairs:
    cells, rat = lat_cells(r, bl)
    m = re.search(r"check (\S+) maxrel=(\S+) bad=(\S+)", note(r))
    cells.append("%s %s bad %s" % m.groups() if m else "-")
    m = re.search(r"ratio=[0-9.]+ vs (.*?) \(median", note(r))
    cells.append(m.group(1) if m else "-")
    rows.append(cells)
    plot_lat.append((r["name"], rat))
hdr = ["function"]
for b in lat_builds:
    hdr += ["ns %s" % b, "base %s" % b, "ratio %s" % b]
hdr += ["check", "baseline"]
emit(hdr, rows, ["l"] + ["r"] * (len(hdr) - 3) + ["l", "l"])
summ = []
for i, b in enumerate(lat_builds):
    v = [p[1][i] for p in plot_lat if p[1][i] is not None]
    if v:
        summ.append("%s: median ratio %.2f, %d of %d functions slower than the baseline (ratio > 1.0)" %
                    (b, median(v), sum(1 for x in v if x > 1.0), len(v)))
for line_ in summ:
    txt.append("  " + line_)
    md.append("- " + line_)
md.append("")
chain = [(table[k], table.get(("latency_chain", table[k]["name"] + " [baseline]", k[2]))) for k in order
         if table[k]["group"] == "latency_chain" and not table[k]["name"].endswith(" [baseline]")]
if chain:
    section("Latency diagnostics: a floor, and the chain through the direction (or distance) only",
            "Not in the count above. The Lambert row is appear's side test alone, without the two "
            "unit-length checks of the robustness contract: what the eval would cost without them. "
            "The sampler rows: the next input chosen from wi (phase, BSDF) or t (medium) alone: what a path "
            "tracer's next call waits for, the pdf and weight going into the throughput beside it. The gap "
            "to the full-chain row is the time spent after the direction (appear's "
            "HG pdf is evaluated at the returned wi, bit for bit pdf(wo, wi); the baseline's from the "
            "sampled cosine).")
    emit(hdr[:-2], [lat_cells(r, bl)[0] for r, bl in chain], ["l"] + ["r"] * (len(hdr) - 3))
if lat_single:
    section("Latency of the other public eval / pdf / sample functions (no baseline)", "ns per call, dependent chain.")
    emit(["function"] + ["ns %s" % b for b in lat_builds],
         [[r["name"]] + [f_ns(ns(r, b)) for b in lat_builds] for r, _ in lat_single], ["l"] + ["r"] * len(lat_builds))

# ---------------------------------------------------------------- files
with open(os.path.join(OUT, "report.md"), "w") as f:
    f.write("\n".join(md) + "\n")
with open(os.path.join(OUT, "bench_all.csv"), "w", newline="") as f:
    w = csv.writer(f)
    w.writerow(["group", "name"] + ["ns_%s" % b for b, _ in TIMED] + ["ir_%s" % b for b, _ in COUNTED] + ["max_err", "note"])
    for k in order:
        r = table[k]
        w.writerow([r["group"], r["name"]] + ["" if ns(r, b) is None else "%.4g" % ns(r, b) for b, _ in TIMED] +
                   ["" if r["ir"].get(b) is None else "%.2f" % r["ir"][b] for b, _ in COUNTED] +
                   ["" if err(r) is None else "%.3g" % err(r), note(r)])


def q(s):
    return '"%s"' % s.replace('"', "'")


def num(v):
    return "NaN" if v is None or v <= 0 else "%.5g" % v


# (a) ns per call of the public functions (no baselines, no special-function variants, no estimator rows)
SKIP_A = re.compile(r"baseline|libm|plain|textbook|listing|quadrature|disabled|no validation|make \(|no compensation|Walter07", re.I)
with open(os.path.join(OUT, "plot_ns.dat"), "w") as f:
    f.write("# idx label ns_O2 ns_O3native ns_clang_O3native\n")
    i = 0
    for k in order:
        r = table[k]
        if r["group"] in ("batch", "variance", "special") + LAT_GROUPS or SKIP_A.search(r["name"] + " " + note(r)):
            continue
        f.write("%d %s %s\n" % (i, q(r["group"] + ": " + r["name"]), " ".join(num(ns(r, b)) for b, _ in TIMED)))
        i += 1
    n_a = i

# (b) speed vs error pairs: x = ns at FAST, y = max err (0 -> floor 1e-9), kind 0 = appear, 1 = baseline
PAIRS = [
    ("special", None), ("phase", "hg sample"), ("microfacet", "lambda"),
    ("batch", "Heitz"), ("batch", "ggx_sample_visible batch"), ("ward", "eval"), ("sggx", "D "), ("energy", "eval"),
    ("fiber", "sigma"),
]
with open(os.path.join(OUT, "plot_err.dat"), "w") as f:
    f.write("# ns_%s max_err kind label\n" % FAST)
    for k in order:
        r = table[k]
        ok = any(r["group"] == g and (s is None or s in r["name"]) for g, s in PAIRS)
        e, t = err(r), ns(r, FAST)
        if not ok or e is None or not t or "disabled" in r["name"]:
            continue
        if "batch vs" in r["name"]:
            continue
        kind = 1 if re.search(r"libm|plain|textbook|baseline|no compensation|quadrature|listing|\(exact\)", r["name"]) else 0
        lab = r["name"] if r["group"] == "special" else r["group"] + ": " + r["name"]
        lab = lab.replace("batch: ggx_sample_visible: ", "GGX VNDF ").replace("batch: ggx_sample_visible batch", "GGX VNDF caps (batch)")
        lab = lab.replace("energy: conductor ", "").replace("hg sample ", "HG ").replace("(Walter07 fit)", "(fit)")
        lab = lab.replace(" (closed form + quadrature)", " (quadrature)").replace("(raw entries, S^-1)", "")
        lab = lab.replace("(plain Eq. 17.1)", "(plain)").replace("(half-vector form)", "").strip()
        f.write("%.5g %.5g %d %s\n" % (t, max(e, 1e-9), kind, q(lab)))

# (c) media: one block per (profile, estimator): tightness rel_eff
with open(os.path.join(OUT, "plot_media.dat"), "w") as f:
    for p in profs:
        for e in ests:
            f.write("# %s %s\n" % (p, e))
            for t in tights:
                v = rel.get((p, t, e))
                if v is not None and v > 0:
                    f.write("%s %.5g\n" % (t, v))
            f.write("\n\n")

# (d) batch vs scalar
with open(os.path.join(OUT, "plot_batch.dat"), "w") as f:
    f.write("# label " + " ".join("scalar_%s batch_%s" % (b, b) for b in timed_builds) + "\n")
    for base, sv, bv in batch_plot:
        f.write(q(base) + " " + " ".join("%s %s" % (num(a), num(b)) for a, b in zip(sv, bv)) + "\n")

# (e) latency ratios appear / baseline, one line per function, one column per build
with open(os.path.join(OUT, "plot_latency.dat"), "w") as f:
    f.write("# idx label " + " ".join("ratio_%s" % b for b, _ in TIMED) + "\n")
    for i, (name, rat) in enumerate(plot_lat):
        by = dict(zip(lat_builds, rat))
        f.write("%d %s %s\n" % (i, q(name), " ".join(num(by.get(b)) for b, _ in TIMED)))

with open(os.path.join(OUT, "plot_vars.gp"), "w") as f:
    f.write("n_lat = %d\n" % len(plot_lat))
    f.write("n_a = %d\nn_est = %d\nn_prof = %d\n" % (n_a, len(ests), len(profs)))
    f.write("ests = %s\nprofs = %s\n" % (q(" ".join(ests)), q(" ".join(profs))))
    f.write("builds = %s\nn_builds = %d\n" % (q(" ".join(timed_builds)), len(timed_builds)))
    f.write("fast = %s\n" % q(FAST))

print("\n".join(txt))
print("\n== report: %s/report.md, joined CSV: %s/bench_all.csv" % (OUT, OUT))
