"""The Python module pendulum_g against the CLI it shares a library with
(docs/python.md), and its numpy functions against independent references:
mpmath at 50 digits, WGS84's defining normal gravity, Feinstein (2005) Table 2.

Run by ctest (test python_module) with PYTHONPATH at the built package and
PENDULUM_G, PENDULUM_WRITE_CATALOGUE, PENDULUM_SOURCE_DIR in the environment.
"""

import glob
import json
import math
import os
import subprocess

import mpmath
import numpy as np
import pytest

import pendulum_g

CLI = os.environ["PENDULUM_G"]
SOURCE = os.environ["PENDULUM_SOURCE_DIR"]
DATA = os.path.join(SOURCE, "data")


def cli(*args, stdin=None):
    return subprocess.run([CLI, *args], input=stdin, capture_output=True, text=True, cwd=SOURCE)


def error_line(stderr):
    """The CLI's error message: its last stderr line, without the prefix."""
    line = stderr.strip().splitlines()[-1]
    assert line.startswith("pendulum-g: error: "), stderr
    return line[len("pendulum-g: error: "):]


def same_answer(args, call):
    """The CLI run with `args` and the module's `call` give the same: equal
    JSON, or the same message, path and status."""
    run = cli(*args)
    if run.returncode == 0:
        assert call() == json.loads(run.stdout)
        return
    assert run.returncode == 1, run.stderr
    with pytest.raises(pendulum_g.InputError) as caught:
        call()
    message = error_line(run.stderr)
    # The CLI puts the scene file's name before a message that does not name it.
    assert message.endswith(str(caught.value)), (message, str(caught.value))
    assert caught.value.status == 1
    assert str(caught.value).startswith(caught.value.path) or caught.value.path == ""


SCENES = sorted(os.path.relpath(p, SOURCE) for p in glob.glob(os.path.join(DATA, "**", "*.json"), recursive=True))


@pytest.mark.parametrize("scene", SCENES)
def test_every_bundled_scene_reduces_as_the_cli_does(scene):
    # Relative to the source folder, as the CLI is run there: the same "input".
    here = os.getcwd()
    os.chdir(SOURCE)
    try:
        same_answer(["reduce", scene], lambda: pendulum_g.reduce(scene))
    finally:
        os.chdir(here)


def test_a_dict_and_text_reduce_as_standard_input_does():
    with open(os.path.join(DATA, "nelson_olsson_1986.json")) as f:
        text = f.read()
    expected = json.loads(cli("reduce", "-", stdin=text).stdout)
    assert pendulum_g.reduce(json.loads(text)) == expected
    assert pendulum_g.reduce(text) == expected
    # The CI's reproduction of Table II: g as the README's run command prints it.
    assert expected["status"] == "ok"


def test_options_as_the_cli_takes_them():
    scene = os.path.join(DATA, "nelson_olsson_1986.json")
    for flags, kwargs in [(["--amplitude-method", "series", "--series-terms", "2"],
                           {"amplitude_method": "series", "series_terms": 2}),
                          (["--negligible-fraction", "0.5"], {"negligible_fraction": 0.5})]:
        assert pendulum_g.reduce(scene, **kwargs) == json.loads(cli("reduce", scene, *flags).stdout)


@pytest.fixture(scope="module")
def catalogue_files(tmp_path_factory):
    """Every case of tests/bad_scenes.json written as a file (write_catalogue)."""
    folder = tmp_path_factory.mktemp("catalogue")
    path = os.path.join(SOURCE, "tests", "bad_scenes.json")
    subprocess.run([os.environ["PENDULUM_WRITE_CATALOGUE"], str(folder), path], check=True)
    with open(path) as f:
        cases = json.load(f)["cases"]
    return [(case, str(folder / f"seed-{i}.json")) for i, case in enumerate(cases)]


def test_the_bad_scene_catalogue_raises_the_cli_messages(catalogue_files):
    assert len(catalogue_files) > 200
    for case, path in catalogue_files:
        # The cases name recordings by absolute paths (as test_cli.cpp runs them).
        same_answer(["reduce", "--allow-outside", path], lambda: pendulum_g.reduce(path, allow_outside=True))
        with pytest.raises(pendulum_g.InputError) as caught:
            pendulum_g.reduce(path, allow_outside=True)
        # test_cli.cpp writes each scene in /tmp, which messages about a
        # recording beside the scene name; here the scene is in `folder`.
        expected = case["error"].replace("/tmp/", os.path.dirname(path) + "/")
        assert expected in str(caught.value), case["name"]


def test_bad_arguments_raise_python_errors_not_crashes():
    with pytest.raises(pendulum_g.InputError) as caught:
        pendulum_g.reduce({"length": {"value": float("nan"), "unit": "m"}})
    assert caught.value.path == "length.value"
    assert isinstance(caught.value, ValueError)
    with pytest.raises(TypeError):
        pendulum_g.reduce(42)
    with pytest.raises(pendulum_g.InputError, match="cannot open the file"):
        pendulum_g.reduce("no/such/scene.json")
    with pytest.raises(ValueError, match="method: got 'agm2'"):
        pendulum_g.reduce(os.path.join(DATA, "nelson_olsson_1986.json"), amplitude_method="agm2")


def test_fit_decay_from_arrays_equals_the_cli_on_the_same_record():
    path = os.path.join(DATA, "nelson_olsson_1986_decay.json")
    with open(path) as f:
        data = json.load(f)["decay"]["data"]
    arrays = {key: data[key] for key in ("time_unit", "amplitude_unit", "times", "amplitudes", "sigma")}
    expected = json.loads(cli("fit-decay", "-", stdin=json.dumps({"decay": {"data": arrays}})).stdout)
    got = pendulum_g.fit_decay(np.array(data["times"]), np.array(data["amplitudes"]), sigma=data["sigma"],
                               time_unit=data["time_unit"], amplitude_unit=data["amplitude_unit"])
    assert got == expected
    assert pendulum_g.fit_decay(scene=path) == json.loads(cli("fit-decay", path).stdout)


def test_fit_decay_names_the_bad_element():
    with pytest.raises(pendulum_g.InputError) as caught:
        pendulum_g.fit_decay([0, 10, 20], [5.0, float("inf"), 4.0])
    assert caught.value.path == "decay.data.amplitudes[1]"


mpmath.mp.dps = 50


def exact_ratio(theta0):
    """T/T0 = 2K(sin^2(theta0/2))/pi at 50 digits (mpmath's K takes m = k^2)."""
    return 2 * mpmath.ellipk(mpmath.sin(mpmath.mpf(theta0) / 2) ** 2) / mpmath.pi


def exact_ratio_as_documented(theta0):
    """exact_ratio at the amplitude the radian form is exact for: above
    90 deg it works from the deficit pi - theta0 with the double pi, 1.2e-16
    below the true one (lib/include/pendulum/amplitude.hpp)."""
    if theta0 <= math.pi / 2:
        return exact_ratio(theta0)
    return exact_ratio(mpmath.pi - (mpmath.mpf(math.pi) - mpmath.mpf(theta0)))


def test_finite_amplitude_against_mpmath_over_the_whole_range():
    # Amplitudes from 1e-8 rad to within 1e-9 rad of pi, as numpy arrays of
    # two shapes: the result keeps the shape, each element within 4 ulp.
    theta = np.concatenate([np.geomspace(1e-8, 1.0, 40), np.linspace(1.0, math.pi - 1e-9, 60)]).reshape(4, 25)
    got = pendulum_g.finite_amplitude(theta)
    excess = pendulum_g.finite_amplitude(theta, excess=True)
    assert got.shape == theta.shape
    for t, ratio, dt in zip(theta.ravel(), got.ravel(), excess.ravel()):
        exact = exact_ratio_as_documented(t)
        assert abs(ratio - float(exact)) <= 4 * np.spacing(float(exact))
        # The excess keeps its relative precision where T/T0 - 1 would not.
        assert abs(dt - float(exact - 1)) <= 4e-15 * float(exact - 1)


def test_finite_amplitude_methods_and_limits():
    theta = np.radians([0.0, 5.0, 30.0])
    assert pendulum_g.finite_amplitude(0.0) == 1.0
    # small_angle: 1 + theta0^2/16 (Nelson & Olsson Eq. 8, first term with sin x ~ x).
    np.testing.assert_allclose(pendulum_g.finite_amplitude(theta, method="small_angle"), 1 + theta ** 2 / 16,
                               rtol=1e-15)
    # series through 2 terms: 1 + k^2/4 + 9k^4/64, k = sin(theta0/2) (Eq. 8).
    k2 = np.sin(theta / 2) ** 2
    np.testing.assert_allclose(pendulum_g.finite_amplitude(theta, method="series", terms=2),
                               1 + k2 / 4 + 9 * k2 ** 2 / 64, rtol=1e-15)
    assert pendulum_g.finite_amplitude([1.0], method="agm")[0] == pendulum_g.finite_amplitude(1.0)
    with pytest.raises(ValueError, match=r"theta0\[1\]: got 3.14"):
        pendulum_g.finite_amplitude([1.0, math.pi, 2.0])
    with pytest.raises(ValueError, match=r"theta0\[0\]: got nan"):
        pendulum_g.finite_amplitude([float("nan")])
    with pytest.raises(ValueError, match="method: got 'elliptic'"):
        pendulum_g.finite_amplitude(1.0, method="elliptic")


def test_normal_gravity_at_the_wgs84_defining_values():
    # WGS84 (NIMA TR8350.2, Table 3.4): normal gravity at the equator
    # 9.7803253359 and at the poles 9.8321849378 m/s^2, on the ellipsoid.
    g = pendulum_g.normal_gravity(np.array([0.0, 90.0, -90.0]))
    np.testing.assert_allclose(g, [9.7803253359, 9.8321849378, 9.8321849378], rtol=0, atol=1e-10)
    # Broadcast: latitudes against heights; the free-air gradient is near
    # -3.086e-6 s^-2 (Torge, Geodesy, Eq. 4.63's leading term).
    grid = pendulum_g.normal_gravity(np.array([[0.0], [45.0]]), np.array([0.0, 1000.0]))
    assert grid.shape == (2, 2)
    assert abs((grid[1, 1] - grid[1, 0]) / 1000 + 3.086e-6) < 0.01e-6
    with pytest.raises(ValueError, match="latitude: got 91"):
        pendulum_g.normal_gravity(91.0)


ARCMINUTE = math.pi / 180 / 60


def test_clock_errors_against_feinstein_table_2():
    # Feinstein (2005) Table 2, Q = 10 000, semi-amplitude 240': the
    # non-damped circular impulse error (s/day) at impulse locations in
    # arcminutes, to the digits printed.
    rows = [(1.0, 0.017994, 0.5e-6), (72.0, 1.3581, 0.5e-4), (216.0, 8.9162, 0.5e-4), (239.76, 93.032, 0.5e-3)]
    locations = np.array([r[0] for r in rows]) * ARCMINUTE
    got = pendulum_g.impulse_error(240 * ARCMINUTE, locations, 1e4)
    for value, (_, printed, half_unit) in zip(got, rows):
        assert abs(value - printed) <= half_unit
    # Airy: an impulse at the position of equilibrium changes no period.
    assert pendulum_g.impulse_error(240 * ARCMINUTE, 0.0, 1e4) == 0.0
    # Circular error: 86400 (2K/pi - 1) s/day (Feinstein Eq. E-2).
    theta = np.array([0.01, 0.1, 1.0])
    expected = [float(86400 * (exact_ratio(t) - 1)) for t in theta]
    np.testing.assert_allclose(pendulum_g.circular_error(theta), expected, rtol=4e-15)
    with pytest.raises(ValueError, match="location: got"):
        pendulum_g.impulse_error(0.1, 0.2, 1e4)


def test_the_session_in_docs_python_md_prints_what_the_page_shows():
    # Each ```python block of the page, run in one namespace from the source
    # folder, prints the ```text block that follows it.
    import contextlib
    import io
    import re
    with open(os.path.join(SOURCE, "docs", "python.md")) as f:
        page = f.read()
    pairs = re.findall(r"```python\n(.*?)```\n\n```text\n(.*?)```", page, re.S)
    assert len(pairs) >= 5
    namespace = {}
    here = os.getcwd()
    os.chdir(SOURCE)
    try:
        for code, shown in pairs:
            printed = io.StringIO()
            with contextlib.redirect_stdout(printed):
                exec(code, namespace)
            assert printed.getvalue() == shown, code
    finally:
        os.chdir(here)
