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


def library(method, with_order=False, leave_one_out=True):
    def run(runner, h, f, order):
        opts = ["--method", method]
        if with_order and order:
            opts += ["--order", str(order)]
        if not leave_one_out:
            opts.append("--no-leave-one-out")
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
}
