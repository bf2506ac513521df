"""pendulum-g in Python: the same answers as the CLI, in Python's types.

reduce(scene), fit_decay(...), read_recording(path), read_table(path) and
batch(folder) give the CLI's JSON as dicts (batch: a list of them, one a
scene); report(scene, path) writes the CLI's page; the physics
functions take and give numpy arrays of any shape. Bad input raises
InputError (a ValueError) with the CLI's message, its JSON path in `.path`
and the CLI's exit status in `.status`. See docs/python.md.
"""

import json
import math
import os
import warnings

from ._core import InputError, circular_error, finite_amplitude, impulse_error, normal_gravity
from . import _core

__all__ = ["InputError", "reduce", "fit_decay", "read_recording", "read_table", "batch", "report", "finite_amplitude", "normal_gravity", "circular_error",
           "impulse_error"]


def _first_non_finite(value, path=""):
    """(JSON path, value) of the first NaN or infinity among a dict's values, or None."""
    if isinstance(value, float) and not math.isfinite(value):
        return path, value
    if isinstance(value, dict):
        items = ((f"{path}.{k}" if path else str(k), v) for k, v in value.items())
    elif isinstance(value, (list, tuple)):
        items = ((f"{path}[{i}]", v) for i, v in enumerate(value))
    else:
        return None
    for inner_path, item in items:
        found = _first_non_finite(item, inner_path)
        if found is not None:
            return found
    return None


def _input_error(path, message):
    error = InputError(f"{path}: {message}")
    error.path, error.status = path, 1
    return error


def _source(scene):
    """(path, text) for a scene given as a dict, JSON text or a path."""
    if isinstance(scene, dict):
        found = _first_non_finite(scene)
        if found is not None:
            raise _input_error(found[0], f"got {found[1]}; expected a finite number (JSON has no NaN or infinity)")
        return None, json.dumps(scene)
    if isinstance(scene, (bytes, bytearray)):
        scene = scene.decode("utf-8")
    if isinstance(scene, str) and scene.lstrip()[:1] in ("{", "["):
        return None, scene
    if isinstance(scene, (str, os.PathLike)):
        return os.fspath(scene), None
    raise TypeError(f"scene: got {type(scene).__name__}; expected a dict, JSON text or a path")


def reduce(scene, *, directory=".", allow_outside=False, negligible_fraction=0.1, amplitude_method="auto",
           series_terms=4):
    """Every period correction the scene needs, and g: `pendulum-g reduce SCENE` as a dict.

    scene: a dict, JSON text, or the path of a scene file. A dict or text is
    read as `reduce -` reads standard input: its "input" is "-", and the
    recordings it names are looked for in `directory` (default: the
    current one). allow_outside, negligible_fraction, amplitude_method
    ("auto", "agm", "series", "small_angle") and series_terms are the CLI's
    --allow-outside, --negligible-fraction, --amplitude-method, --series-terms.
    """
    path, text = _source(scene)
    return json.loads(_core.reduce_json(path, text, os.fspath(directory), allow_outside, negligible_fraction,
                                        amplitude_method, series_terms))


def fit_decay(times=None, amplitudes=None, *, sigma=None, time_unit="s", amplitude_unit="deg", model=None,
              scene=None, directory=".", allow_outside=False):
    """α and β of dθ0/dt = −αθ0 − βθ0² fitted to a decay record: `pendulum-g fit-decay` as a dict.

    Either arrays (times in `time_unit`, amplitudes in `amplitude_unit`,
    sigma a common or per-point uncertainty of the amplitudes in
    `amplitude_unit`), checked as a scene's decay.data is, or scene=: a
    dict, JSON text or path holding `decay` with `data`. model forces
    "both", "linear_only" or "quadratic_only".
    """
    if scene is None:
        if times is None or amplitudes is None:
            raise TypeError("fit_decay needs times and amplitudes, or scene=")
        data = {"time_unit": time_unit, "amplitude_unit": amplitude_unit,
                "times": [float(t) for t in times], "amplitudes": [float(a) for a in amplitudes]}
        if sigma is not None:
            if hasattr(sigma, "__len__"):
                data["sigmas"] = [float(s) for s in sigma]
            else:
                data["sigma"] = float(sigma)
        scene = {"decay": {"data": data}}
    elif times is not None or amplitudes is not None:
        raise TypeError("fit_decay takes arrays or scene=, not both")
    path, text = _source(scene)
    return json.loads(_core.fit_decay_json(path, text, os.fspath(directory), allow_outside, model))


def read_recording(path, *, columns=None, set=None, format="auto", bob_width_m=None, length_m=None, range=None,
                   stamps_per_period=None):
    """A phone, photogate or video-tracker recording reduced: `pendulum-g import PATH` as a dict.

    The dict holds every key of the CLI's JSON (format, periods, period,
    amplitude_range, timing, decay, columns, glitches, notes: the `timing`
    and `decay` objects paste into a scene), and as numpy arrays:
    "crossings_s" (each zero crossing or gate passage, s), "swings" (per
    half swing: start_s, end_s, peak_time_s, amplitude_deg; NaN where the
    recording gives no amplitude) and "period_curve" (per full period: time_s
    from the first crossing, amplitude_deg, period_s). columns, set,
    format, bob_width_m, length_m, range=(start, end) (s) or "all" (the
    whole record; default: the clean stretch) and stamps_per_period are
    import's --columns, --set, --format, --bob-width-m, --length-m, --range
    and --stamps-per-period.
    """
    whole = isinstance(range, str)
    if whole and range != "all":
        raise ValueError(f"range: got {range!r}; expected (start, end) in seconds or \"all\"")
    core = _core.read_recording(os.fspath(path), format, set or "", columns or "", bob_width_m, length_m,
                                None if range is None or whole else (float(range[0]), float(range[1])), whole,
                                stamps_per_period)
    result = json.loads(core.pop("json"))
    result.update(core)
    return result


def read_table(path, *, columns=None, oscillations=None):
    """A table of settings and periods read into a scene: `pendulum-g import --table PATH` as a dict.

    columns and oscillations are import's --columns ("l:cm,u,t10:s,u") and
    --oscillations. The warnings the CLI prints (a unit taken from the
    numbers alone) are Python warnings (UserWarning) here.
    """
    text, found = _core.read_table(os.fspath(path), columns or "", oscillations)
    for w in found:
        warnings.warn(f"{os.fspath(path)}: {w}", stacklevel=2)
    return json.loads(text)


def batch(scenes, *, allow_outside=False):
    """Many scenes reduced to one row each: `pendulum-g batch SCENES --format jsonl` as a list of dicts.

    scenes: a folder (its *.json, in name order), a scene file, or a list of
    them. Each row is the CLI's JSON line (input, ok, g_m_s2,
    g_uncertainty_m_s2, z, status, warnings, error, ...), so that
    pandas.DataFrame(batch(folder)) is the class's table; a scene that
    fails is a row with ok false and its error, not an exception. Entries
    of a folder that are no scenes give a UserWarning, as the CLI's notes.
    """
    paths = [scenes] if isinstance(scenes, (str, os.PathLike)) else list(scenes)
    lines, skipped = _core.batch_lines([os.fspath(p) for p in paths], allow_outside)
    for name, why in skipped:
        warnings.warn(f"skipped {name}: {why}", stacklevel=2)
    return [json.loads(line) for line in lines]


def report(scene, path=None, *, plot=None, format=None, set=None, columns=None, directory=".", allow_outside=False,
           negligible_fraction=0.1, amplitude_method="auto", series_terms=4):
    """The HTML page (or, with plot=, one SVG plot) of `pendulum-g report SCENE -o PATH`.

    scene: a scene as for reduce(), or the path of a recording. The page is
    written to `path` whole or not at all (never over an input), or
    returned as text when path is None. plot ("corrections", "budget",
    "decay", "series", "pivot-scan"; a recording's "signal", "amplitude",
    "period-amplitude"), format (a recording's family), set and columns are
    report's --plot, --format, --set and --columns. The warnings the CLI
    prints are Python warnings here.
    """
    source, text = _source(scene)
    page, found = _core.report(source, text, os.fspath(directory), allow_outside,
                               "" if path is None else os.fspath(path), plot or "", format, set or "", columns or "",
                               negligible_fraction, amplitude_method, series_terms)
    for w in found:
        warnings.warn(w, stacklevel=2)
    return page
