"""The demo's contact section: the law at the contact points of a FE block.

Runs the bundled contact scenario ``frictionlab/data/contact/pmma_block.toml`` through
the same code path as ``frictionlab contact`` (outputs in ``OUT/contact/``) and returns
a report section with the slip-front map and one measured sentence.
"""

from __future__ import annotations

import contextlib
import time
from pathlib import Path

from frictionlab.demo import DemoContext, bundled_scenario, law_rows, load_bundled
from frictionlab.demo.fretting import fretting_section
from frictionlab.errors import FrictionlabError
from frictionlab.io.atomic import write_text_atomic
from frictionlab.io.report import Section, format_value

__all__ = ["CONTACT_SECTIONS", "bundled_contact_scenario", "contact_section"]


def bundled_contact_scenario(name: str) -> contextlib.AbstractContextManager[Path]:
    """A filesystem path to the bundled contact scenario ``name`` (e.g. ``"pmma_block"``)."""
    return bundled_scenario(name, "contact")


#: The contact law's rows of the report: (key, unit).
_LAW_KEYS = (("mu_s", "-"), ("mu_k", "-"), ("alpha_n", "Pa/m"), ("alpha_t", "Pa/m"),
             ("u", "1/m"), ("kappa", "1/m"), ("xi", "1/s"))  # fmt: skip


def contact_section(ctx: DemoContext) -> Section:
    """The law in a finite-element contact model: precursor slip at the trailing edge"""
    from frictionlab.app.contact import run_contact_scenario, write_contact_results
    from frictionlab.contact import front_arrival, slip_front
    from frictionlab.schema.contact import load_contact as load_contact_scenario

    rel = "contact"
    out = ctx.out_dir / rel
    scenario, text = load_bundled("pmma_block", "contact", load_contact_scenario)
    start = time.perf_counter()
    with ctx.progress("contact: PMMA-like block") as progress:
        history = run_contact_scenario(scenario, progress)
    elapsed = time.perf_counter() - start
    if not history.success:
        raise FrictionlabError(f"demo contact: {history.message}")
    write_contact_results(out, scenario, history, elapsed)
    write_text_atomic(out / "scenario.toml", text)

    peak = history.peak_index
    arrival = front_arrival(history, scenario.front_ratio)
    extent = slip_front(history, scenario.front_ratio)
    width = scenario.block.width
    sliding = history.stage > 0
    iterations = history.iterations[sliding]
    sec = Section(
        "The law in a finite-element contact model",
        "frictionlab contact puts the subloading-friction law at the Gauss points of the "
        "bottom edge of a plane-strain elastic block (scikit-fem) on a rigid base, presses "
        "it and drags it by its top edge, and solves every load step by Newton's method "
        "with the law's consistent tangent. Here a PMMA-like block, 100 mm x 25 mm, under "
        "1 MPa: slide 30 um, hold 10 s, slide 20 um. The drag's moment unloads the trailing "
        "edge, so sliding starts there while the rest of the interface is still in the "
        "sub-sliding state.",
        law=law_rows(scenario.params, _LAW_KEYS),  # compared with the first law table
        parameters=_parameters(scenario),
    )
    sec.add_figure(
        f"{rel}/interface_map.png",
        "Along the interface (x from the trailing edge) against the travel of the top: the "
        "ratio R of the law (left; grey where the trailing edge lifts off) with the front "
        "of the zone in the sliding state (R >= 0.99, white) and the peak force (red), and "
        "the plastic slip (right). The sliding zone grows from the trailing edge; after the "
        "hold the contact has recovered (R < 1) and a second front runs.",
    )
    sec.add_figure(
        f"{rel}/friction.png",
        "The block's friction ratio Q/P (tangential over normal force of the interface) "
        "against the top displacement: a static peak, softening, recovery during the hold "
        "and a smaller restart peak.",
    )
    before = float(extent[: peak + 1].max())
    sentence = (
        f"Measured: the peak Q/P = {history.friction_ratio[peak]:.3f} comes at a top "
        f"displacement of {history.top_displacement[peak] * 1e6:.1f} um, when the sliding "
        f"zone has reached {100 * before / width:.0f} % of the interface from the trailing "
        "edge; "
    )
    if arrival is None:
        sentence += "the sliding zone never spans the whole interface. "
    else:
        sentence += (
            f"it spans the whole interface at {100 * arrival['fraction_of_peak']:.0f} % of "
            f"the peak force, {'after' if arrival['row'] > peak else 'before'} the peak. "
        )
    sentence += (
        f"Newton took {iterations.mean():.1f} iterations per sliding step on average "
        f"(at most {int(iterations.max())}), {history.n_rows - 1} steps in {elapsed:.1f} s."
    )
    sec.notes.append(sentence)
    return sec


def _parameters(scenario: object) -> list[tuple[str, str, str]]:
    from frictionlab.schema.contact import ContactScenario

    assert isinstance(scenario, ContactScenario)
    b = scenario.block
    nx, ny = b.cells
    rows = [
        ("E", format_value(b.E), "Pa"),
        ("nu", format_value(b.nu), "-"),
        ("width x height", f"{b.width * 1e3:g} x {b.height * 1e3:g}", "mm"),
        ("mesh", f"{nx} x {ny} {b.element} cells", ""),
        ("pressure", format_value(scenario.normal.value), "Pa"),
    ]
    return rows


#: The contact model's demo sections, in report order.
CONTACT_SECTIONS = (contact_section, fretting_section)
