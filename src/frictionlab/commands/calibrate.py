"""``frictionlab calibrate CONFIG.toml --out DIR``: fit the law to tribometer curves.

Reads the starting law, the fitted parameters and the measured curves with their
programmes (:mod:`frictionlab.io.calibration_config`), fits them
(:func:`frictionlab.calibration.fit_law`), profiles the poorly identified parameters and
writes ``fitted.toml``, ``fit.json``, ``curves.csv``, the figures and ``report.html``.

Exit codes: 2 bad input or bad data (one line naming the key or file; nothing written),
1 failed computation (the driver fails at the starting law), 0 success.
"""

from __future__ import annotations

import argparse
import time
from typing import Any

import numpy as np

from frictionlab.commands._output import add_run_arguments
from frictionlab.commands._progress import progress_bar

HELP = "fit the law's parameters to tribometer curves and write fitted.toml, fit.json, a report"


def add_parser(sub: argparse._SubParsersAction) -> None:
    parser = sub.add_parser("calibrate", help=HELP, description=HELP)
    add_run_arguments(parser, "calibration file (TOML)", "fit.profile=false or --set law.mu_s=0.6",
                      input_name="config", plots=False)  # fmt: skip
    parser.set_defaults(handler=run)


def run(args: argparse.Namespace) -> int:
    from frictionlab.io.calibration_config import load_calibration
    from frictionlab.io.output_set import check_out, output_set

    out = check_out(args.out, args.overwrite)
    cfg = load_calibration(args.config, args.set)  # every input and data check happens here
    with output_set(out, args.overwrite) as oset:
        return _fit_and_write(args, cfg, oset)


def _fit_and_write(args: argparse.Namespace, cfg: Any, oset: Any) -> int:
    from frictionlab.calibration import evaluate_columns, fit_law, profile_likelihood
    from frictionlab.io.calibration_results import CalibrationRun, write_calibration

    start = time.perf_counter()
    x0 = np.array([[float(getattr(cfg.params, n))] for n in cfg.names])
    start_models = tuple(evaluate_columns(cfg.params, cfg.names, x0, c)[0] for c in cfg.curves)
    with progress_bar(f"calibrate {args.config.name}", enabled=not args.quiet) as progress:
        fit = fit_law(
            cfg.params, cfg.curves, cfg.names, cfg.bounds,
            max_nfev=cfg.max_evaluations, progress=progress,
        )  # fmt: skip
    profiles = {}
    if cfg.profile:
        for name in fit.worst_identified(cfg.profile_max):
            with progress_bar(f"profile {name}", enabled=not args.quiet) as progress:
                profiles[name] = profile_likelihood(
                    fit, cfg.curves, name, points=cfg.profile_points, progress=progress
                )
    result = CalibrationRun(cfg, fit, start_models, profiles)
    written = write_calibration(oset.staging, result, args.config.parent)
    written = [oset.shown(p) for p in written]
    if not args.quiet:
        from frictionlab.io.calibration_results import identifiability

        elapsed = time.perf_counter() - start
        print(f"frictionlab calibrate: {len(cfg.curves)} curve(s), {fit.n_points} samples, "
              f"{fit.nfev} evaluations ({fit.runs} driver runs) in {elapsed:.2f} s; "
              f"{fit.message}")  # fmt: skip
        print(f"{'parameter':>10} {'start':>12} {'fitted':>12} {'stderr':>10} {'rel':>7}")
        for j, name in enumerate(fit.names):
            se, rel = fit.stderr[j], fit.relative_stderr[j]
            print(f"{name:>10} {fit.start[j]:>12.5g} {fit.values[j]:>12.6g} {se:>10.3g} "
                  f"{rel:>7.1%}")  # fmt: skip
        print(f"residual std {np.sqrt(fit.residual_variance):.3g} (friction ratio)")
        for line in identifiability(fit, profiles):
            print("  " + line)
        print("wrote " + ", ".join(str(p) for p in written))
    return 0
