"""``probesim sensor MODEL``: a sensor model's quality indices and electronics, and ``--list`` of the bundled ones."""

from __future__ import annotations

from pathlib import Path

__all__ = ["main_sensor", "format_model", "format_readings"]


def format_model(model) -> str:
    """The lines ``probesim sensor`` prints: what the model is and its indices (f2, f1′ and the DIN 5032-7
    class for an illuminance head, the mismatch factor F under common lights), its electronics."""
    ix = model.indices()
    lines = [f"{ix['name']}: {ix['title']}",
             f"  reports {ix['reports']}, calibrated under {ix['calibration']} at normal incidence"
             f" (channels: {', '.join(ix['channels'])})",
             f"  angular response {ix['angular']}: ∫r dω = {ix['integral_sr']:.5g} sr (cosine: π = 3.1416), "
             f"f2 = {100 * ix['f2']:.2f}%"]
    if "f1_prime" in ix:
        lines.append(f"  spectral: f1′ = {100 * ix['f1_prime']:.2f}%; DIN 5032-7 class {ix['din_5032_7_class']} "
                     "(limits f1′/f2: L 1.5/1.5%, A 3/1.5%, B 6/3%, C 9/6%)")
    lines.append("  mismatch factor F (true = F × reading): " +
                 ", ".join(f"{k} {v:.4f}" for k, v in ix["mismatch_F"].items()))
    el = ix.get("electronics")
    if el:
        lines.append(f"  electronics: {el['bits']}-bit, gains {', '.join(f'{g:g}' for g in el['gains'])}, integration "
                     f"{', '.join(f'{t:g}' for t in el['integration_ms'])} ms, firmware {el['firmware']}, "
                     f"{'auto-ranging' if el['auto_range'] else 'fixed setting'}; full scale "
                     f"{el['full_scale'][0]:.4g} (most sensitive) to {el['full_scale'][1]:.4g} (least)")
    else:
        lines.append("  electronics: none (the device reports the optics' signal)")
    if ix["source"]:
        lines.append(f"  source: {ix['source']}")
    lines += [f"  note: {n}" for n in ix["notes"]]
    return "\n".join(lines)


def format_readings(rows, limit: int = 30) -> list[str]:
    """One console line per modelled sensor: its optics signal and what the device reports."""
    out = []
    for r in rows:
        v = r.values
        if "model" not in v:
            continue
        opt = next((k for k in v if k.startswith("optics_") and "_stderr_" not in k), None)
        dev = next((k for k in v if k.startswith("device_") and k.split("_")[1] not in
                    ("noise", "counts", "saturated", "gain", "integration")), None)
        if opt is None:
            continue
        unit = {"lx": "lx", "W_m2": "W/m²", "umol_m2_s": "µmol/m²/s"}.get(opt.split("_", 2)[2], "")
        se = next((k for k in v if k.startswith("optics_") and "_stderr_" in k), None)
        line = f"{r.sensor.name[:24]:<24} through {v['model']}: optics {v[opt]:.4g} {unit}"
        if se is not None:
            line += f" ± {v[se]:.3g}"
        if dev is not None:
            line += f", device {v[dev]:.4g} {unit}"
            counts = [f"{k[len('device_counts_'):]} {v[k]}" for k in v if k.startswith("device_counts_")]
            if counts:
                line += f" (counts {', '.join(counts)}; gain {v['device_gain']:g}, {v['device_integration_ms']:g} ms"
                line += ", SATURATED)" if v.get("device_saturated") else ")"
        out.append(line)
        if len(out) == limit:
            break
    return out


def main_sensor(spec: str | None, list_only: bool) -> int:
    from simulator.errors import UserError
    from simulator.sensor_models.model import bundled_names, load_model

    if list_only or spec is None:
        for name in bundled_names():
            m = load_model(name)
            print(f"{name:<24} {m.title}")
        return 0
    if not spec:
        raise UserError("sensor: name a model (probesim sensor --list)")
    print(format_model(load_model(spec, Path.cwd(), "sensor")))
    return 0
