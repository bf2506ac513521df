"""pendulum-g in Python: the same answers as the CLI, in Python's types.

reduce(scene) and fit_decay(...) give the CLI's JSON as dicts; the physics
functions take and give numpy arrays of any shape. Bad input raises
InputError (a ValueError) with the CLI's message, its JSON path in `.path`
and the CLI's exit status in `.status`. See docs/python.md.
"""

import json
import math
import os

from ._core import InputError, circular_error, finite_amplitude, impulse_error, normal_gravity
from . import _core

__all__ = ["InputError", "reduce", "fit_decay", "finite_amplitude", "normal_gravity", "circular_error",
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
