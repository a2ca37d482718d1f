# SPDX-License-Identifier: GPL-3.0-or-later
# Estimators measured by corpus.py: the library methods as they are, and
# prototypes of candidate intervals built from `gridfree extrapolate` output
# (docs/EXTRAPOLATION.md "Coverage on other codes' series" names the forms and
# their sources). Each estimator maps (runner, h, f, formal order) to
# {verdict, f0, u0, f1, u1} or None when it prints no uncertainty.
import json
import os
import statistics
import subprocess
import tempfile


class Runner:
    """Runs `gridfree extrapolate` once per distinct (series, options)."""

    def __init__(self, gridfree):
        self.gridfree, self.cache = gridfree, {}

    def __call__(self, h, f, *opts):
        key = (tuple(h), tuple(f), opts)
        if key not in self.cache:
            with tempfile.NamedTemporaryFile("w", suffix=".json", delete=False) as tmp:
                json.dump({"h": list(h), "f": list(f)}, tmp)
            try:
                out = subprocess.run([self.gridfree, "extrapolate", tmp.name, *opts], capture_output=True,
                                     text=True, check=True).stdout
            finally:
                os.unlink(tmp.name)
            self.cache[key] = json.loads(out)
        return self.cache[key]


def summary(r):
    if r.get("f0") is None or r["grids"][0].get("u") is None:
        return None
    return {"verdict": r["verdict"]["value"], "f0": r["f0"], "u0": r.get("u0"), "f1": r["grids"][0]["f"],
            "u1": r["grids"][0]["u"], "p": r.get("p"), "sigma": r.get("sigma_re") or 0.0}


def library(method, with_order=False, leave_one_out=True, range_floor=True):
    def run(runner, h, f, order):
        opts = ["--method", method]
        if with_order and order:
            opts += ["--order", str(order)]
        if not leave_one_out:
            opts.append("--no-leave-one-out")
        if not range_floor:
            opts.append("--no-range-floor")
        return summary(runner(h, f, *opts))
    return run


def widen(w, f0_values, sigma, factor=1.25, verdict=None):
    """f₁ ± U₁ and f0 ± U₀ grown to hold every f0 in f0_values with the factor."""
    out = dict(w)
    reach = max(abs(v - w["f1"]) for v in f0_values)
    out["u1"] = max(w["u1"], factor * reach + sigma)
    spread = max(abs(v - w["f0"]) for v in f0_values)
    if w.get("u0") is not None:
        out["u0"] = max(w["u0"], factor * spread + w["u0"])
    if verdict:
        out["verdict"] = verdict
    return out


def xing_stern(runner, h, f, order):
    """Declared order p_th with the factor of safety of Xing & Stern (2010):
    P = p_obs/p_th, FS = 2.45 − 0.85 P (0 < P ≤ 1), 16.4 P − 14.8 (P > 1);
    U₁ = FS |f0 − f₁| + σ with f0 from the capped fit. Without a declared order
    or an observed one the capped U₁ stands."""
    w = summary(runner(h, f, "--method", "capped", "--no-leave-one-out"))
    if w is None or not order or not w["p"] or w["p"] <= 0:
        return w
    P = w["p"] / order
    fs = 2.45 - 0.85 * P if P <= 1 else 16.4 * P - 14.8
    out = dict(w)
    out["u1"] = max(w["u1"], fs * abs(w["f0"] - w["f1"]) + w["sigma"])
    if w.get("u0") is not None:
        out["u0"] = max(w["u0"], fs * abs(w["f0"] - w["f1"]) + w["sigma"])
    return out


def leave_one_out_f0(runner, h, f, method):
    """f0 of the window without its coarsest and without its finest grid
    (each needs ≥ 4 grids)."""
    vals = []
    if len(h) >= 5:
        for hh, ff in ((h[:-1], f[:-1]), (h[1:], f[1:])):
            r = runner(hh, ff, "--method", method, "--no-leave-one-out")
            if r.get("f0") is not None:
                vals.append(r["f0"])
    return vals


def consistency(method="capped"):
    """converged only when f0 without the coarsest grid and without the
    finest both lie within the window's U₀ of its f0 (else pre-asymptotic);
    the intervals grow to hold both leave-one-out f0."""
    def run(runner, h, f, order):
        w = summary(runner(h, f, "--method", method, "--no-leave-one-out"))
        if w is None:
            return None
        loo = leave_one_out_f0(runner, h, f, method)
        agree = loo and w.get("u0") is not None and all(abs(v - w["f0"]) <= w["u0"] for v in loo)
        verdict = w["verdict"]
        if verdict == "converged" and not agree:
            verdict = "pre-asymptotic"
        return widen(w, [w["f0"]] + loo, w["sigma"], verdict=verdict)
    return run


def model_average_with(kappa=None, alpha=1.0):
    """Spread of f0 over the admissible fits (Eça & Hoekstra's four
    expansions and the capped fit): U₁ = max(capped U₁, 1.25 · max|f0_k − f₁| + σ).
    Admissible: σ_k < alpha · R_f and, with kappa, σ_k ≤ kappa · the smallest σ."""
    def run(runner, h, f, order):
        w = summary(runner(h, f, "--method", "capped", "--no-leave-one-out"))
        if w is None:
            return None
        fits = runner(h, f, "--method", "eh14", "--no-leave-one-out").get("fits", {})
        rng = (max(f) - min(f)) / (len(f) - 1)
        cands = [(w["f0"], w["sigma"])]
        for name in ("power", "first", "second", "mixed"):
            fit = fits.get(name) or {}
            if fit.get("f0") is None or fit.get("sigma") is None:
                continue
            if name == "power" and not fit.get("p_found"):
                continue
            if rng > 0 and fit["sigma"] >= alpha * rng:
                continue  # a fit that does not describe the data is not admissible
            cands.append((fit["f0"], fit["sigma"]))
        if kappa is not None:
            best = min(sg for _, sg in cands)
            cands = [(v, sg) for v, sg in cands if sg <= kappa * best or v == w["f0"]]
        return widen(w, [v for v, _ in cands], w["sigma"])
    return run


model_average = model_average_with()


def triplets(runner, h, f, order):
    """Median and MAD of the three-grid extrapolations of every consecutive
    triplet (robust sub-triplet estimate, after Krysl 2022): f0 = median,
    U₁ = 1.25 |f0 − f₁| + 3 s, U₀ = 0.25 |f0 − f₁| + 3 s with s = 1.4826 MAD."""
    r = runner(h, f, "--method", "capped", "--no-leave-one-out")
    w = summary(r)
    if w is None:
        return None
    ext = [t["f_ext"] for t in r.get("gci", []) if t.get("f_ext") is not None]
    if len(ext) < 2:
        return w
    med = statistics.median(ext)
    mad = statistics.median(abs(e - med) for e in ext)
    out = dict(w)
    out["f0"] = med
    out["u1"] = 1.25 * abs(med - w["f1"]) + 3 * 1.4826 * mad
    out["u0"] = 0.25 * abs(med - w["f1"]) + 3 * 1.4826 * mad
    return out


def combined_with(average):
    def combined(runner, h, f, order):
        """Declared order (Xing & Stern factor) + leave-one-out consistency +
        model averaging: the widest of the three intervals, the verdict of the
        consistency rule, not converged when the data contradict the order."""
        parts = [e(runner, h, f, order) for e in (xing_stern, consistency(), average)]
        if any(part is None for part in parts):
            return None
        out = dict(parts[1])
        p = parts[0].get("p")
        if order and out["verdict"] == "converged" and (not p or abs(p / order - 1) > 0.25):
            out["verdict"] = "pre-asymptotic"  # the data contradict the declared order
        out["u1"] = max(part["u1"] for part in parts)
        u0 = [part["u0"] for part in parts if part.get("u0") is not None]
        out["u0"] = max(u0) if u0 else None
        return out
    return combined


class PowerFits:
    """Least-squares fits f = f0 + c h^p (unweighted) on fixed grids h, p
    the member of exponents with the smallest residual: a grid search over p
    with the linear fit in (f0, c) solved exactly at each. The sums that
    depend on h alone are made once; per data set the residual is
    Σf² − f0 Σf − c Σx f (the normal equations)."""

    def __init__(self, h, exponents):
        n = len(h)
        self.n, self.terms = n, []
        for p in exponents:
            x = [v ** p for v in h]
            sx, sxx = sum(x), sum(v * v for v in x)
            self.terms.append((x, sx, n * sxx - sx * sx))

    def f0(self, f):
        n, sf, sff = self.n, sum(f), sum(v * v for v in f)
        best = None
        for x, sx, det in self.terms:
            sxf = sum(a * b for a, b in zip(x, f))
            c = (n * sxf - sx * sf) / det
            f0 = (sf - c * sx) / n
            ssr = sff - f0 * sf - c * sxf
            if best is None or ssr < best[0]:
                best = (ssr, f0)
        return best[1]


BOOT_EXPONENTS = [0.5 + 0.05 * k for k in range(33)]  # 0.5 … 2.1, the capped fit's range
BOOT_CACHE = {}


def bootstrap_with(replicates=400, level=0.95, seed=20261207, pairs=False):
    """Residual bootstrap of the least-squares power-law fit (Efron &
    Tibshirani 1993, ch. 9: resample the fit's residuals, rescaled by
    √(n/(n − 3)) for the three fitted parameters, add them to the fitted
    values, refit with p free in [0.5, 2.1]); the percentile interval
    [q_lo, q_hi] of the replicates' f0 at the given level.
    f0 ± U₀ = the interval about the capped f0 (U₀ = its farther end);
    f₁ ± U₁ holds it (U₁ = max |q − f₁|). Verdict: the capped method's.
    Fitted values and residuals are the capped fit's (`fhat` per grid).
    With pairs: resample the (h, f) pairs themselves instead (a draw with
    fewer than three distinct grids is drawn again)."""
    import random

    def interval(h, f, fhat):
        key = (tuple(h), tuple(f), replicates, level, seed, pairs)
        if key in BOOT_CACHE:
            return BOOT_CACHE[key]
        n = len(h)
        scale = (n / (n - 3)) ** 0.5 if n > 3 else 1.0
        res = [scale * (fi - gi) for fi, gi in zip(f, fhat)]
        rng = random.Random(seed)
        fits = PowerFits(h, BOOT_EXPONENTS)

        def draw():
            if not pairs:
                return fits.f0([g + rng.choice(res) for g in fhat])
            while True:
                pick = [rng.randrange(n) for _ in range(n)]
                if len(set(pick)) >= 3:
                    return PowerFits([h[i] for i in pick], BOOT_EXPONENTS).f0([f[i] for i in pick])
        f0s = sorted(draw() for _ in range(replicates))
        BOOT_CACHE[key] = (f0s[int((1 - level) / 2 * (replicates - 1))], f0s[int((1 + level) / 2 * (replicates - 1))])
        return BOOT_CACHE[key]

    def run(runner, h, f, order):
        r = runner(h, f, "--method", "capped", "--no-leave-one-out")
        w = summary(r)
        if w is None:
            return None
        fitted = {g["h"]: g.get("fhat") for g in r["grids"]}
        if any(fitted.get(v) is None for v in h):
            return w
        lo, hi = interval(h, f, [fitted[v] for v in h])
        out = dict(w)
        out["u0"] = max(abs(lo - w["f0"]), abs(hi - w["f0"]))
        out["u1"] = max(abs(lo - w["f1"]), abs(hi - w["f1"]))
        return out
    return run


def widest_of(*estimators):
    """The widest of several estimators' intervals, the first one's verdict."""
    def run(runner, h, f, order):
        parts = [e(runner, h, f, order) for e in estimators]
        if any(part is None for part in parts):
            return None
        out = dict(parts[0])
        out["u1"] = max(part["u1"] for part in parts)
        u0 = [part["u0"] for part in parts if part.get("u0") is not None]
        out["u0"] = max(u0) if u0 else None
        return out
    return run


def data_range_floor(estimator, factor, per_interval=False):
    """An `unreliable` window's U no smaller than factor · Δ_M, the largest
    difference between its grids' values: the fallback Eça & Hoekstra (2014)
    use when the data admit no fit (there with factor 3)."""
    def run(runner, h, f, order):
        w = estimator(runner, h, f, order)
        if w is None or w["verdict"] != "unreliable":
            return w
        out = dict(w)
        dm = (max(f) - min(f)) / ((len(f) - 1) if per_interval else 1)
        out["u1"] = max(w["u1"], factor * dm)
        if w.get("u0") is not None:
            out["u0"] = max(w["u0"], factor * dm)
        return out
    return run


ESTIMATORS = {
    # the library as it is (leave-one-out test on, no order declared)
    "averaged": library("averaged"),
    "capped": library("capped"),
    "fm": library("fm"),
    "eh14": library("eh14"),
    # the library before the bias checks (2026-12-06)
    "capped-before": library("capped", leave_one_out=False),
    "fm-before": library("fm", leave_one_out=False),
    "eh14-before": library("eh14", leave_one_out=False),
    # with the corpus' declared formal order (--order)
    "averaged+order": library("averaged", with_order=True),
    "capped+order": library("capped", with_order=True),
    "fm+order": library("fm", with_order=True),
    "eh14+order": library("eh14", with_order=True),
    "xing-stern": xing_stern,
    "consistency": consistency(),
    "model-average": model_average,
    "triplets": triplets,
    "combined": combined_with(model_average),
    "combined-3": combined_with(model_average_with(3.0)),
    "combined-a0.3": combined_with(model_average_with(None, 0.3)),
    # averaged before its floor on unreliable windows (2026-12-07), and floors tried
    "averaged-before-floor": library("averaged", range_floor=False),
    "averaged+order-before-floor": library("averaged", with_order=True, range_floor=False),
    "averaged+order+dm1": data_range_floor(library("averaged", with_order=True, range_floor=False), 1.0),
    "averaged+order+dm3": data_range_floor(library("averaged", with_order=True, range_floor=False), 3.0),
    "averaged+order+dphi3": data_range_floor(library("averaged", with_order=True, range_floor=False), 3.0,
                                             per_interval=True),
    "bootstrap": bootstrap_with(),
    "bootstrap-pairs": bootstrap_with(pairs=True),
    "averaged+bootstrap": widest_of(library("averaged", range_floor=False), bootstrap_with()),
    "averaged+order+bootstrap": widest_of(library("averaged", with_order=True, range_floor=False),
                                          bootstrap_with()),
}
