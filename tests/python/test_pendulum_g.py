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
import select
import signal
import subprocess
import sys
import time

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


def test_an_amplitude_sweep_without_its_length_reduces_as_the_cli_does():
    scene = cli("import", os.path.join(DATA, "amplitude_sweep.csv")).stdout
    expected = json.loads(cli("reduce", "-", stdin=scene).stdout)
    assert expected["kind"] == "amplitude_sweep" and expected["g"] is None
    assert pendulum_g.reduce(scene) == expected


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


def test_a_fit_that_fails_raises_and_prints_nothing(capfd):
    # A decay record's last time 1e300 min: Ceres's evaluation fails, and it
    # says so through glog on stderr unless the module silences it, as the CLI does.
    with open(os.path.join(DATA, "nelson_olsson_1986.json")) as f:
        scene = json.load(f)
    scene["decay"] = {"data": {"time_unit": "min", "amplitude_unit": "deg", "times": [0, 1, 2, 3, 4, 1e300],
                               "amplitudes": [5.05, 4.91, 4.82, 4.74, 4.65, 4.18], "sigma": 0.05}}
    text = json.dumps(scene)
    with pytest.raises(pendulum_g.InputError) as caught:
        pendulum_g.reduce(text)
    assert str(caught.value) == error_line(cli("reduce", "-", stdin=text).stderr).removeprefix("-: ")
    assert "the fit of Eq. (25) failed (Residual and Jacobian evaluation failed.)" in str(caught.value)
    assert capfd.readouterr().err == ""


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



NELSON_OLSSON = os.path.join(DATA, "nelson_olsson_1986.json")
GATE = os.path.join(DATA, "recordings", "vernier_photogate.csv")
LENGTHS = os.path.join(DATA, "pendulum_lengths_table.csv")


@pytest.mark.parametrize("args, call", [
    # Issue 42, item 4: series_terms=0 took the 596 us finite-amplitude row as negligible.
    (["reduce", NELSON_OLSSON, "--amplitude-method", "series", "--series-terms", "0"],
     lambda: pendulum_g.reduce(NELSON_OLSSON, amplitude_method="series", series_terms=0)),
    (["reduce", NELSON_OLSSON, "--negligible-fraction", "nan"],
     lambda: pendulum_g.reduce(NELSON_OLSSON, negligible_fraction=float("nan"))),
    (["reduce", NELSON_OLSSON, "--negligible-fraction", "-0.5"],
     lambda: pendulum_g.reduce(NELSON_OLSSON, negligible_fraction=-0.5)),
    (["report", NELSON_OLSSON, "--series-terms", "0"], lambda: pendulum_g.report(NELSON_OLSSON, series_terms=0)),
    # Item 11: an internal error, no amplitudes, or a wrong count taken.
    (["import", GATE, "--length-m", "-1"], lambda: pendulum_g.read_recording(GATE, length_m=-1)),
    (["import", GATE, "--length-m", "inf"], lambda: pendulum_g.read_recording(GATE, length_m=float("inf"))),
    (["import", GATE, "--length-m", "1e300"], lambda: pendulum_g.read_recording(GATE, length_m=1e300)),
    (["import", GATE, "--bob-width-m", "-0.02"], lambda: pendulum_g.read_recording(GATE, bob_width_m=-0.02)),
    (["import", GATE, "--stamps-per-period", "3"], lambda: pendulum_g.read_recording(GATE, stamps_per_period=3)),
    (["import", LENGTHS, "--oscillations", "0"], lambda: pendulum_g.read_table(LENGTHS, oscillations=0)),
    (["amplitude", "--theta0-deg", "10", "--method", "series", "--terms", "0"],
     lambda: pendulum_g.finite_amplitude(0.1, method="series", terms=0)),
])
def test_arguments_are_refused_with_the_cli_options_message(args, call):
    # One table of ranges (pendulum/argument_ranges.hpp) for both: the CLI
    # says "--series-terms: got 0; expected ...", Python "series_terms: ...".
    run = cli(*args)
    assert run.returncode == 2, run.stderr
    option, message = run.stderr.splitlines()[0].split(": ", 1)
    with pytest.raises(ValueError) as caught:
        call()
    assert str(caught.value) == option.lstrip("-").replace("-", "_") + ": " + message


def test_the_physics_refuses_what_a_scene_refuses():
    # Item 6: nan, 3.8e11 and 5229 m/s^2 were returned for heights off the Earth.
    for height in (1e300, 1e20, -6.4e6):
        scene = {"length": {"value": 1.0, "unit": "m"}, "amplitude": {"value": 1.0, "unit": "deg"},
                 "timing": {"oscillations_per_trial": 10, "unit": "s", "resolution": 0.01, "trials": [20.06]},
                 "site": {"latitude": {"value": 45.0, "unit": "deg"},
                          "height": {"value": height, "unit": "m"}, "height_reference": "ellipsoid"}}
        with pytest.raises(pendulum_g.InputError) as scene_error:
            pendulum_g.reduce(scene)
        with pytest.raises(ValueError) as caught:
            pendulum_g.normal_gravity(45.0, height)
        assert str(caught.value) == str(scene_error.value).replace("site.height.value", "height")
    # A denormal Q or amplitude gave nan; a clock scene takes Q from 1.
    with pytest.raises(ValueError, match=r"^q: got [0-9.e-]+; expected a quality factor from 1 to 1e15$"):
        pendulum_g.impulse_error(0.1, 0.1, 1e-320)
    with pytest.raises(ValueError, match=r"^theta0: got [0-9.e-]+ rad; expected an angle from 1e-9 rad to below 180 deg$"):
        pendulum_g.impulse_error(1e-320, 0.0, 1e4)
    with pytest.raises(ValueError, match=r"^q: got 1; expected a Q large enough that the impulse"):
        pendulum_g.impulse_error(3.0, 0.1, 1.0)


def test_no_nan_or_infinity_for_finite_arguments_in_range():
    # Every argument over its whole range, ends included: a finite answer or
    # a ValueError, never NaN or infinity.
    latitudes = np.linspace(-90.0, 90.0, 37)[:, None]
    heights = np.concatenate([np.linspace(-12e3, 100e3, 57), [-12e3 + 1e-9, 100e3 - 1e-9]])
    assert np.isfinite(pendulum_g.normal_gravity(latitudes, heights)).all()
    below_pi = np.nextafter(math.pi, 0.0)
    amplitudes = np.concatenate([[0.0, 5e-324, 1e-300, 1e-9], np.linspace(1e-6, below_pi, 200), [below_pi]])
    for method in ("exact", "series", "small_angle"):
        assert np.isfinite(pendulum_g.finite_amplitude(amplitudes, method=method)).all()
        assert np.isfinite(pendulum_g.finite_amplitude(amplitudes, method=method, excess=True)).all()
    assert np.isfinite(pendulum_g.circular_error(amplitudes)).all()
    for theta0 in np.concatenate([[1e-9, 1e-6, 0.01, 0.5, 2.0, 3.0, 3.14, below_pi]]):
        for location in (0.0, 5e-324, theta0 / 2, np.nextafter(theta0, 0.0), theta0):
            for q in (1.0, 1.5, 100.0, 1e4, 1e10, 1e15):
                try:
                    value = pendulum_g.impulse_error(theta0, location, q)
                except ValueError as e:
                    assert "keeps the swing below 180 deg" in str(e)
                    continue
                assert np.isfinite(value), (theta0, location, q)


@pytest.mark.parametrize("theta0_rad, deg, got", [
    # An element's value was std::to_string's: 1e300 as 309 digits, -1e-300
    # as "-0.000000" (a minus zero refused?), NaN as "nan".
    (1e300, "1e300", "1e+300"), (-1e-300, "-1e-300", "-1e-300"), (float("nan"), "nan", "NaN"),
    (math.pi, "180", None),
])
def test_an_amplitude_out_of_range_is_named_as_the_cli_names_it(theta0_rad, deg, got):
    # One range (ranges::amplitude, in rad; amplitude_deg for --theta0-deg).
    run = cli("amplitude", "--theta0-deg", deg)
    assert run.returncode == 1, run.stderr
    assert error_line(run.stderr) == (f"--theta0-deg: got {got or deg} deg; expected an amplitude from 0 to below "
                                      "180 deg (at 180 deg and beyond the pendulum goes over the top)")
    shown = got or format(math.pi, ".10g")
    expected = (f"theta0[1]: got {shown} rad; expected an amplitude from 0 to below pi rad (at 180 deg and beyond "
                "the pendulum goes over the top)")
    theta0 = np.array([0.1, theta0_rad, 0.2])
    for call in (lambda: pendulum_g.finite_amplitude(theta0), lambda: pendulum_g.circular_error(theta0),
                 lambda: pendulum_g.finite_amplitude(theta0, method="series"),
                 lambda: pendulum_g.finite_amplitude(theta0, method="small_angle")):
        with pytest.raises(ValueError) as caught:
            call()
        assert str(caught.value) == expected


def test_finite_amplitude_into_an_out_that_overlaps_its_input():
    # numpy's out= reads the input as it was (np.sin(x[:5], out=x[1:]) is
    # np.sin of x[:5] before the call); item 5 wrote [1, 1, 1, 1, 1].
    for method in ("exact", "series"):
        for into, source in ((slice(1, 6), slice(0, 5)), (slice(0, 5), slice(1, 6))):
            x = np.radians(np.linspace(10.0, 170.0, 6))
            expected = pendulum_g.finite_amplitude(x[source].copy(), method=method)
            pendulum_g.finite_amplitude(x[source], method=method, out=x[into])
            np.testing.assert_array_equal(x[into], expected)


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


def test_finite_amplitude_against_mpmath_over_the_whole_range():
    # Amplitudes from 1e-8 rad to within 1e-9 rad of pi, as numpy arrays of
    # two shapes: the result keeps the shape, each element within 4 ulp.
    theta = np.concatenate([np.geomspace(1e-8, 1.0, 40), np.linspace(1.0, math.pi - 1e-9, 60)]).reshape(4, 25)
    got = pendulum_g.finite_amplitude(theta)
    excess = pendulum_g.finite_amplitude(theta, excess=True)
    assert got.shape == theta.shape
    for t, ratio, dt in zip(theta.ravel(), got.ravel(), excess.ravel()):
        exact = exact_ratio(t)
        assert abs(ratio - float(exact)) <= 4 * np.spacing(float(exact))
        # The excess keeps its relative precision where T/T0 - 1 would not.
        assert abs(dt - float(exact - 1)) <= 4e-15 * float(exact - 1)


def test_finite_amplitude_exact_near_180_deg_for_radians():
    # Deficits pi - theta0 from 0.3 rad to the last double below pi, each
    # amplitude taken as the double it is: within 1e-15 of mpmath at 50
    # digits, as the degree form is (the deficit from the double pi alone,
    # 1.2e-16 short, was 1.0e-14 off at 179.9 deg).
    theta = np.append(math.pi - np.geomspace(0.3, 1e-15, 60), np.nextafter(math.pi, 0.0))
    theta = np.append(theta, np.radians([160.0, 170.0, 179.0, 179.9, 179.99]))
    got = pendulum_g.finite_amplitude(theta)
    for t, ratio in zip(theta, got):
        exact = exact_ratio(t)
        assert abs(ratio - exact) <= 1e-15 * exact, (t, float((ratio - exact) / exact))


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
    with pytest.raises(ValueError, match=r"theta0\[0\]: got NaN rad"):
        pendulum_g.finite_amplitude([float("nan")])
    with pytest.raises(ValueError, match="method: got 'elliptic'"):
        pendulum_g.finite_amplitude(1.0, method="elliptic")


def test_finite_amplitude_into_out_as_numpy_does():
    theta = np.radians(np.linspace(0.0, 179.0, 1000)).reshape(10, 100)
    expected = pendulum_g.finite_amplitude(theta)
    for method in ("exact", "series"):
        out = np.full_like(theta, np.nan)
        assert pendulum_g.finite_amplitude(theta, method=method, out=out) is out
        np.testing.assert_array_equal(out, pendulum_g.finite_amplitude(theta, method=method))
    in_place = theta.copy()  # the amplitudes themselves may be the output
    pendulum_g.finite_amplitude(in_place, out=in_place)
    np.testing.assert_array_equal(in_place, expected)
    with pytest.raises(ValueError, match="out: its shape is not theta0's"):
        pendulum_g.finite_amplitude(theta, out=np.empty(1000))
    with pytest.raises(TypeError, match="out: expected a C-contiguous numpy array of float64"):
        pendulum_g.finite_amplitude(theta, out=np.empty((10, 100), dtype=np.float32))
    with pytest.raises(TypeError, match="out: expected a C-contiguous"):
        pendulum_g.finite_amplitude(theta, out=np.empty((100, 10)).T)
    read_only = np.empty_like(theta)
    read_only.flags.writeable = False
    with pytest.raises(ValueError, match="out: the array is read-only"):
        pendulum_g.finite_amplitude(theta, out=read_only)


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


ARRAY_KEYS = ("crossings_s", "swings", "period_curve")
RECORDINGS = sorted(os.path.relpath(p, SOURCE) for p in glob.glob(os.path.join(DATA, "recordings", "*"))
                    if not p.endswith(".json"))


def in_source(call):
    """call() run from the source folder, where the CLI runs."""
    here = os.getcwd()
    os.chdir(SOURCE)
    try:
        return call()
    finally:
        os.chdir(here)


@pytest.mark.parametrize("recording", RECORDINGS)
def test_every_bundled_recording_reads_as_import_does(recording):
    run = cli("import", recording)
    if run.returncode != 0:  # two tracks, and no --set to choose
        same_answer_recording(["import", recording], lambda: in_source(lambda: pendulum_g.read_recording(recording)))
        return
    got = in_source(lambda: pendulum_g.read_recording(recording))
    assert {k: v for k, v in got.items() if k not in ARRAY_KEYS} == json.loads(run.stdout)
    crossings = got["crossings_s"]
    assert isinstance(crossings, np.ndarray) and np.all(np.diff(crossings) > 0)
    # Each full period spans crossings_per_period crossings; the curve has
    # one point a period, within the crossings' span.
    periods = got["period_curve"]
    assert len(periods["period_s"]) == len(periods["time_s"]) == len(periods["amplitude_deg"])
    assert np.all(periods["time_s"] <= crossings[-1] - crossings[0])
    swings = got["swings"]
    assert np.all(swings["end_s"] > swings["start_s"])
    # The decay record's amplitudes are the swings' (deg), where known.
    if got["decay"] is not None:
        known = swings["amplitude_deg"][np.isfinite(swings["amplitude_deg"])]
        assert np.isin(got["decay"]["data"]["amplitudes"], known).all()


def test_recording_options_as_import_takes_them():
    recording = os.path.join("data", "recordings", "tracker_glitchy_end.txt")
    run = cli("import", recording, "--range", "0:20")
    got = in_source(lambda: pendulum_g.read_recording(recording, range=(0, 20)))
    assert {k: v for k, v in got.items() if k not in ARRAY_KEYS} == json.loads(run.stdout)
    two = os.path.join("data", "recordings", "tracker_two_tracks.txt")
    run = cli("import", two, "--set", "mass B")
    got = in_source(lambda: pendulum_g.read_recording(two, set="mass B"))
    assert {k: v for k, v in got.items() if k not in ARRAY_KEYS} == json.loads(run.stdout)
    headerless = os.path.join("data", "recordings", "tracker_headerless_xy.txt")
    run = cli("import", headerless, "--columns", "t:s,x:m,y:m")
    got = in_source(lambda: pendulum_g.read_recording(headerless, columns="t:s,x:m,y:m"))
    assert {k: v for k, v in got.items() if k not in ARRAY_KEYS} == json.loads(run.stdout)


def test_bad_recordings_raise_the_import_messages(tmp_path):
    cases = {"missing.csv": None, "one_line.csv": "t,theta\n", "letters.csv": "t,theta\n0,1\n0.1,x\n0.2,3\n0.3,4\n"}
    for name, text in cases.items():
        path = str(tmp_path / name)
        if text is not None:
            with open(path, "w") as f:
                f.write(text)
        same_answer_recording(["import", path], lambda: pendulum_g.read_recording(path))
    scene = os.path.join(DATA, "nelson_olsson_1986.json")
    same_answer_recording(["import", scene], lambda: pendulum_g.read_recording(scene))
    with pytest.raises(ValueError, match="format: got 'csv'"):
        pendulum_g.read_recording(scene, format="csv")
    # The values refused are named, as the CLI's --range names its text.
    for span, shown in (((5, 1), "(5.0, 1.0)"), ((float("nan"), 1), "(nan, 1.0)"), ((0, float("inf")), "(0.0, inf)")):
        with pytest.raises(ValueError) as caught:
            pendulum_g.read_recording(scene, range=span)
        assert str(caught.value) == (f"range: got {shown}; expected (start, end) in seconds of the recording's clock, "
                                     "start before end")


def test_range_all_reads_as_import_does():
    # The clean stretch by default, the whole record with range="all" (issue 38).
    glitchy = "data/recordings/tracker_glitchy_end.txt"
    for args, kwargs in ((["import", glitchy], {}), (["import", "--range", "all", glitchy], {"range": "all"})):
        run = cli(*args)
        assert run.returncode == 0, run.stderr
        got = in_source(lambda: pendulum_g.read_recording(glitchy, **kwargs))
        assert {k: v for k, v in got.items() if k not in ARRAY_KEYS} == json.loads(run.stdout)
        assert bool(got["cut"]) == (not kwargs)
    with pytest.raises(ValueError, match="expected .start, end. in seconds or \"all\""):
        pendulum_g.read_recording(glitchy, range="everything")


def same_answer_recording(args, call):
    """The CLI fails with status 1 and call() raises its message."""
    run = cli(*args)
    assert run.returncode == 1, (args, run.stdout, run.stderr)
    with pytest.raises(pendulum_g.InputError) as caught:
        call()
    assert error_line(run.stderr).endswith(str(caught.value)), (run.stderr, str(caught.value))
    assert caught.value.status == 1


@pytest.mark.parametrize("table", ["data/pendulum_lengths_table.csv", "data/pivot_scan_table.csv"])
def test_tables_read_as_import_does(table):
    run = cli("import", table)
    assert run.returncode == 0, run.stderr
    assert in_source(lambda: pendulum_g.read_table(table)) == json.loads(run.stdout)


def test_a_table_options_and_errors_as_import_has_them(tmp_path):
    path = str(tmp_path / "t.csv")
    with open(path, "w") as f:
        f.write("0.5,14.2,0.1\n0.7,16.8,0.1\n0.9,19.0,0.1\n1.1,21.0,0.1\n")
    run = cli("import", path, "--columns", "l:m,t10:s,u")
    assert run.returncode == 0, run.stderr
    assert pendulum_g.read_table(path, columns="l:m,t10:s,u") == json.loads(run.stdout)
    with open(path, "w") as f:
        f.write("length_m,period_s\n0.5,1.42\n0.7,x\n")
    same_answer_recording(["import", "--table", path], lambda: pendulum_g.read_table(path))


def test_batch_of_the_class_folder_equals_the_cli_rows():
    run = cli("batch", "data/class", "--format", "jsonl")
    lines = run.stdout.splitlines()
    rows = in_source(lambda: pendulum_g.batch("data/class"))
    assert rows == [json.loads(line) for line in lines[:-1]]
    assert json.loads(lines[-1])["class"] is True and len(rows) == 3


def test_batch_rows_of_failures_and_skipped_entries_as_the_cli_gives_them(tmp_path):
    folder = tmp_path / "class"
    folder.mkdir()
    (folder / "sub").mkdir()
    (folder / "notes.txt").write_text("no scene\n")
    (folder / "bad.json").write_text('{"length": {"value": -1, "unit": "m"}}')
    with open(os.path.join(DATA, "nelson_olsson_1986.json")) as f:
        (folder / "good.json").write_text(f.read())
    run = cli("batch", str(folder))
    assert run.returncode == 1
    with pytest.warns(UserWarning) as caught:
        rows = pendulum_g.batch(folder)
    assert rows == [json.loads(line) for line in run.stdout.splitlines()[:-1]]
    assert [r["ok"] for r in rows] == [False, True]
    notes = [line[len("pendulum-g: note: "):] for line in run.stderr.splitlines() if line.startswith("pendulum-g: note")]
    assert [str(w.message) for w in caught] == notes and len(notes) == 2
    assert pendulum_g.batch([str(folder / "good.json")]) == rows[1:]


@pytest.mark.parametrize("args", [["data/nelson_olsson_1986.json"], ["data/kater_reversible_pendulum.json"],
                                  ["data/recordings/phyphox_gyroscope.csv"],
                                  ["data/nelson_olsson_1986_decay.json", "--plot", "decay"]])
def test_report_writes_the_cli_page(tmp_path, args):
    expected, got = tmp_path / "cli.out", tmp_path / "module.out"
    run = cli("report", *args, "-o", str(expected))
    assert run.returncode == 0, run.stderr
    plot = args[args.index("--plot") + 1] if "--plot" in args else None
    import warnings
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        assert in_source(lambda: pendulum_g.report(args[0], got, plot=plot)) is None
    assert got.read_bytes() == expected.read_bytes()
    assert [f"pendulum-g: warning: {w.message}" for w in caught] == run.stderr.splitlines()
    assert in_source(lambda: pendulum_g.report(args[0], plot=plot)) == expected.read_text()


def test_report_refuses_what_the_cli_refuses(tmp_path):
    scene = tmp_path / "scene.json"
    with open(os.path.join(DATA, "nelson_olsson_1986.json")) as f:
        scene.write_text(f.read())
    before = scene.read_bytes()
    with pytest.raises(ValueError, match="is the input"):
        pendulum_g.report(scene, scene)
    assert scene.read_bytes() == before
    with pytest.raises(OSError, match="output: cannot write .*: Is a directory"):
        pendulum_g.report(scene, tmp_path)
    bad = tmp_path / "bad.json"
    bad.write_text('{"length": {"value": -1, "unit": "m"}}')
    same_answer_recording(["report", str(bad), "-o", str(tmp_path / "r.html")],
                          lambda: pendulum_g.report(bad, tmp_path / "r.html"))
    assert not (tmp_path / "r.html").exists()


def test_the_notebook_is_the_page_and_runs_to_its_outputs():
    # docs/python.ipynb is tests/tools/python_notebook.py's from the page, and
    # Debian's Jupyter (nbclient, ipykernel) runs it to the outputs it stores.
    import copy
    import sys
    import nbclient
    import nbformat
    sys.path.insert(0, os.path.join(SOURCE, "tests", "tools"))
    import python_notebook
    with open(os.path.join(SOURCE, "docs", "python.md")) as f:
        expected = python_notebook.text(f.read())
    with open(os.path.join(SOURCE, "docs", "python.ipynb")) as f:
        stored = f.read()
    assert stored == expected, "run tests/tools/python_notebook.py"
    notebook = nbformat.reads(stored, as_version=4)
    ran = copy.deepcopy(notebook)
    nbclient.NotebookClient(ran, timeout=300, kernel_name="python3",
                            resources={"metadata": {"path": SOURCE}}).execute()
    code = [(a, b) for a, b in zip(notebook.cells, ran.cells) if a.cell_type == "code"]
    assert len(code) >= 8
    for stored_cell, ran_cell in code:
        printed = "".join(o.get("text", "") for o in ran_cell.outputs if o.output_type == "stream")
        assert printed == "".join(o["text"] for o in stored_cell.outputs), stored_cell.source


def cpu_seconds(pid):
    """User and system time (s) process `pid` has used so far (Linux's /proc/PID/stat, fields 14 and 15)."""
    with open(f"/proc/{pid}/stat", encoding="ascii") as stat:
        fields = stat.read().rsplit(")", 1)[1].split()
    return (int(fields[11]) + int(fields[12])) / os.sysconf("SC_CLK_TCK")


def test_ctrl_c_stops_a_long_call(tmp_path):
    """Ctrl-C (SIGINT) during a long call raises KeyboardInterrupt within a
    fraction of a second, not after the whole call (issue 42): a table of
    10^4 lengths, the most a table holds by default, takes seconds to reduce
    (12.6 s for the CLI on the 2-core machine this was written on)."""
    rows = ["length (m),period (s),sigma_T (s)"]
    for i in range(10000):
        length = 0.3 + i * 1e-4
        rows.append(f"{length:.4f},{2 * math.pi * math.sqrt(length / 9.81):.5f},0.001")
    (tmp_path / "lengths.csv").write_text("\n".join(rows) + "\n")
    scene = tmp_path / "scene.json"
    scene.write_text(json.dumps({"amplitude": "not recorded", "observations": {"table": "lengths.csv"}}))
    script = ("import time, pendulum_g\n"
              "print('ready', flush=True)\n"
              "try:\n"
              f"    pendulum_g.reduce({str(scene)!r})\n"
              "    print('finished', flush=True)\n"
              "except KeyboardInterrupt:\n"
              "    print('interrupted', flush=True)\n")
    child = subprocess.Popen([sys.executable, "-c", script], stdout=subprocess.PIPE, text=True)
    assert child.stdout.readline() == "ready\n"
    time.sleep(0.5)  # well inside the call: it starts microseconds after "ready"
    sent = time.monotonic()
    before = cpu_seconds(child.pid)
    child.send_signal(signal.SIGINT)
    assert select.select([child.stdout], [], [], 300)[0], "no line 300 s after Ctrl-C"
    out = child.stdout.readline()
    stopped = time.monotonic() - sent
    spent = cpu_seconds(child.pid) - before
    child.communicate(timeout=300)
    assert out == "interrupted\n"
    # The work the call did after Ctrl-C, in its own processor time: the
    # wall clock stretches with the machine's load (2.2 s with two other
    # processes per core, beside 12 s for the whole call).
    assert spent < 1.0, f"{spent:.2f} s of processor time ({stopped:.2f} s) from Ctrl-C to KeyboardInterrupt"
