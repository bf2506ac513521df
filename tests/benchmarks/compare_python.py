#!/usr/bin/python3
"""The Python module pendulum_g against its peers, in one run (docs/python.md).

Usage (Debian's python3 with python3-scipy and python3-mpmath; the module
built, the CLI beside it):
    PYTHONPATH=build/python /usr/bin/python3 tests/benchmarks/compare_python.py build/cli/pendulum-g

1. T/T0 over 10^6 amplitudes drawn uniformly in [0, 90 deg] and in
   [0, 179 deg] (seed 1):
   pendulum_g.finite_amplitude (exact) against
   2*scipy.special.ellipk(np.sin(t/2)**2)/np.pi (one thread, the same array):
   the median time and page faults (ru_minflt) of a call, over 5 rounds of
   5 calls of each, the rounds alternating, so that each one is timed in its
   own steady state under the same load; and each one's worst error against
   mpmath at 40 digits over the first 10^4 of the same amplitudes, in units
   of the result's ulp. Then the same with each one writing into arrays it
   reuses (numpy's out=: pendulum_g's one output, scipy's formula step by
   step into one buffer), which leaves out the page faults of fresh memory.
   Alternating call by call instead would charge each one's fresh result
   with the page faults of the memory glibc handed back to the system when
   the other's temporaries were freed (docs/python.md, "Speed").
2. The Nelson-Olsson scene: pendulum_g.reduce in this process against a
   subprocess call of `pendulum-g reduce` on the same file, median of 21
   calls each, alternating.
"""
import os
import resource
import statistics
import subprocess
import sys
import time

import mpmath
import numpy as np
import scipy.special

import pendulum_g


def medians(f, g, rounds, calls):
    """(seconds, page faults) medians of a call of f and of g: `rounds` rounds
    of `calls` calls of each, the rounds alternating (the same load for both)."""
    samples = ([], [])
    for _ in range(rounds):
        for fn, out in zip((f, g), samples):
            for _ in range(calls):
                faults = resource.getrusage(resource.RUSAGE_SELF).ru_minflt
                start = time.perf_counter()
                result = fn()
                seconds = time.perf_counter() - start
                out.append((seconds, resource.getrusage(resource.RUSAGE_SELF).ru_minflt - faults))
                del result  # freed before the next call, as a loop over calls would
    return tuple((statistics.median(s for s, _ in out), statistics.median(n for _, n in out)) for out in samples)


def worst_ulp(values, theta):
    mpmath.mp.dps = 40
    worst = 0.0
    for v, t in zip(values, theta):
        exact = 2 * mpmath.ellipk(mpmath.sin(mpmath.mpf(float(t)) / 2) ** 2) / mpmath.pi
        worst = max(worst, abs(float((mpmath.mpf(float(v)) - exact) / np.spacing(float(exact)))))
    return worst


def main():
    cli = sys.argv[1]
    for top_deg in (90.0, 179.0):
        theta = np.random.default_rng(1).uniform(0.0, np.radians(top_deg), 1_000_000)
        scipy_ratio = lambda: 2 * scipy.special.ellipk(np.sin(theta / 2) ** 2) / np.pi  # noqa: E731
        (ours, ours_faults), (peer, peer_faults) = medians(
            lambda: pendulum_g.finite_amplitude(theta), scipy_ratio, 5, 5)
        sample = theta[:10_000]
        print(f"finite_amplitude, 10^6 amplitudes uniform in [0, {top_deg:g} deg], median of 25 calls:")
        print(f"  pendulum_g.finite_amplitude      {ours * 1e3:8.2f} ms   worst error "
              f"{worst_ulp(pendulum_g.finite_amplitude(sample), sample):7.1f} ulp   page faults {ours_faults:5.0f}")
        print(f"  scipy.special.ellipk formula     {peer * 1e3:8.2f} ms   worst error "
              f"{worst_ulp(scipy_ratio()[:10_000], sample):7.1f} ulp   page faults {peer_faults:5.0f}")
        print(f"  ratio scipy / pendulum_g         {peer / ours:8.1f}x")
        ours_out, peer_out = np.empty_like(theta), np.empty_like(theta)

        def scipy_into():
            np.multiply(theta, 0.5, out=peer_out)
            np.sin(peer_out, out=peer_out)
            np.square(peer_out, out=peer_out)
            scipy.special.ellipk(peer_out, out=peer_out)
            np.multiply(peer_out, 2 / np.pi, out=peer_out)

        (ours, _), (peer, _) = medians(lambda: pendulum_g.finite_amplitude(theta, out=ours_out), scipy_into, 5, 5)
        assert np.array_equal(ours_out, pendulum_g.finite_amplitude(theta))
        assert np.allclose(peer_out, scipy_ratio(), rtol=1e-15, atol=0)
        print("  the same into reused arrays (out=):")
        print(f"  pendulum_g.finite_amplitude      {ours * 1e3:8.2f} ms")
        print(f"  scipy.special.ellipk formula     {peer * 1e3:8.2f} ms")
        print(f"  ratio scipy / pendulum_g         {peer / ours:8.1f}x")

    scene = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "data", "nelson_olsson_1986.json")
    (in_process, _), (subprocess_call, _) = medians(
        lambda: pendulum_g.reduce(scene),
        lambda: subprocess.run([cli, "reduce", scene], check=True, capture_output=True), 21, 1)
    print("reduce of data/nelson_olsson_1986.json, median of 21:")
    print(f"  pendulum_g.reduce                {in_process * 1e3:8.3f} ms")
    print(f"  subprocess pendulum-g reduce     {subprocess_call * 1e3:8.3f} ms")
    print(f"  ratio subprocess / module        {subprocess_call / in_process:8.1f}x")


if __name__ == "__main__":
    main()
