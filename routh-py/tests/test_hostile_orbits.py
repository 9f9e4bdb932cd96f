"""Hostile inputs to the periodic-orbit and section functions, as a table: each case is a call
and what it must give — an error of a kind and naming what was wrong, or a right answer checked
against the pendulum's closed form. And Ctrl-C: a section or a family stops at once."""

import json
import math
import os
import signal
import threading
import time

import numpy as np
import pytest

import routh

PENDULUM = "kinetic = 0.5 * omega.dot(diag(inertia) * omega), potential = mgl * gamma.z"
B = routh.Model(PENDULUM, {"inertia": [1.0, 2.0, 3.0], "mgl": 1.5})
# The same body, heavier: its hanging steady motion has another energy.
C = routh.Model(PENDULUM, {"inertia": [1.0, 2.0, 3.0], "mgl": 4.0})
W0 = math.sqrt(1.5)  # the linear frequency of swings about e₁
G = [0.0, math.sin(0.5), -math.cos(0.5)]  # a swing of 0.5 rad about e₁


def elliptic_k(m):
    a, g = 1.0, math.sqrt(1.0 - m)
    for _ in range(60):
        a, g = 0.5 * (a + g), math.sqrt(a * g)
    return math.pi / (2.0 * a)


#: The pendulum's period at amplitude 0.5 (closed form).
T = 4 * elliptic_k(math.sin(0.25) ** 2) / W0


def hanging(m):
    return min(m.steady_motions(0.0), key=lambda s: s.energy)


def with_field(o, **fields):
    """The orbit `o` read back from its JSON with `fields` changed."""
    d = json.loads(o.to_json())
    d.update(fields)
    return routh.PeriodicOrbit.from_json(json.dumps(d))


@pytest.fixture(scope="module")
def o():
    return B.periodic_orbit([0, 0, 0], G, 2 * math.pi / W0)


# name → (call(o), exception, words its message must hold)
REFUSED = {
    "a path of 10^12 samples": (lambda o: B.orbit_path(o, 10**12), routh.RouthError, "1000000"),
    "a path of 10^30 samples": (lambda o: B.orbit_path(o, 10**30), OverflowError, None),
    "a path of 10^8 samples": (lambda o: B.orbit_path(o, 10**8), routh.RouthError, "1000000"),
    "energy bounds that exclude the start": (
        lambda o: B.lyapunov_family(hanging(B), 0, energy_bounds=(5, 6)),
        routh.RouthError,
        "outside the bounds",
    ),
    "a range that excludes the orbit": (
        lambda o: B.continue_orbit(o, (5, 6)),
        routh.RouthError,
        "outside the range",
    ),
    "a period guess of 1e-9": (
        lambda o: B.periodic_orbit([0, 0, 0], G, 1e-9),
        routh.RouthError,
        "period_guess",
    ),
    "omega of 1e200": (
        lambda o: B.periodic_orbit([1e200, 0, 0], G, T),
        routh.RouthError,
        "non-finite",
    ),
    "an initial amplitude of 1e-300": (
        lambda o: B.lyapunov_family(hanging(B), 0, initial_amplitude=1e-300),
        routh.RouthError,
        "initial_amplitude",
    ),
    "rtol 1e-300": (
        lambda o: B.periodic_orbit([0, 0, 0], G, T, rtol=1e-300),
        routh.RouthError,
        "rtol",
    ),
    "newton_tol 1e-300": (
        lambda o: B.continue_orbit(o, (-2, 0), newton_tol=1e-300),
        routh.RouthError,
        "newton_tol",
    ),
    "a steady motion of another model": (
        lambda o: B.lyapunov_family(hanging(C), 0, max_orbits=5),
        routh.RouthError,
        "not a steady motion of this model",
    ),
    "an orbit of another model": (
        lambda o: B.continue_orbit(C.periodic_orbit([0, 0, 0], G, 3.0), (-10, 10), max_orbits=5),
        routh.RouthError,
        "not a periodic orbit of this model",
    ),
    "a section of no orbits": (
        lambda o: B.poincare_section(0.0, -1.0, orbits=0),
        routh.RouthError,
        "orbits",
    ),
    "a section of 10^12 crossings": (
        lambda o: B.poincare_section(0.0, -1.0, orbits=2, crossings=10**12),
        routh.RouthError,
        "crossings",
    ),
    "a section of 10^4 x 10^4 crossings": (
        lambda o: B.poincare_section(0.0, -1.0, orbits=10_000, crossings=10_000),
        routh.RouthError,
        "budget",
    ),
    "a path of an orbit with a negative period": (
        lambda o: B.orbit_path(with_field(o, period=-1.0), 10),
        routh.RouthError,
        "orbit.period",
    ),
    "the crossings of an orbit with a period of 1e300": (
        lambda o: B.orbit_crossings(with_field(o, period=1e300)),
        routh.RouthError,
        "over its period",
    ),
    "True as a period": (lambda o: B.periodic_orbit([0, 0, 0], G, True), TypeError, "bool"),
    "True as an energy": (lambda o: B.poincare_section(0.0, True), TypeError, "bool"),
    "True as a bound": (lambda o: B.continue_orbit(o, (True, 2)), TypeError, "bool"),
    "True as energy bounds": (
        lambda o: B.lyapunov_family(hanging(B), 0, energy_bounds=(-2, True)),
        TypeError,
        "bool",
    ),
    "True as a tolerance": (
        lambda o: B.periodic_orbit([0, 0, 0], G, T, rtol=True),
        TypeError,
        "bool",
    ),
}


@pytest.mark.parametrize("name", list(REFUSED))
def test_hostile_orbit_inputs_are_refused_with_a_clear_message(o, name):
    call, kind, words = REFUSED[name]
    t0 = time.monotonic()
    with pytest.raises(kind) as e:
        call(o)
    if words is not None:
        assert words in str(e.value), str(e.value)
    # Refused before any long work (a generous bound: the calls that are refused after their
    # start's correction take milliseconds).
    assert time.monotonic() - t0 < 20


def test_a_period_guess_of_three_periods_gives_the_least_period():
    # The guess 3T converges to the orbit traversed three times; the least period is returned.
    o = B.periodic_orbit([0, 0, 0], G, 3 * T)
    assert abs(o.period - T) < 1e-8 * T


@pytest.mark.parametrize("scale", [1e160, 1e-200, 1e-320, 1e308])
def test_section_normals_of_any_length_are_the_same_plane(o, scale):
    # n and s·n are the same plane: the crossings of the swing through γ₂ = 0 (the plane normal
    # to e₂) are those of the unit normal.
    unit = B.orbit_crossings(o, normal=[0, 1, 0])
    assert np.allclose(B.orbit_crossings(o, normal=[0, scale, 0]), unit, rtol=0, atol=1e-12)


def test_a_section_gives_every_orbit_asked():
    sec = B.poincare_section(0.0, -1.0, orbits=1000, crossings=1)
    assert len(sec.points) == 1000 and sec.starts.shape == (1000, 6)


def interrupt_after(seconds):
    """Sends this process SIGINT (Ctrl-C) after `seconds`, from another thread."""
    timer = threading.Timer(seconds, lambda: os.kill(os.getpid(), signal.SIGINT))
    timer.start()
    return timer


@pytest.mark.skipif(threading.current_thread() is not threading.main_thread(),
                    reason="signals reach the main thread only")
@pytest.mark.parametrize("analysis", ["section", "family"])
def test_ctrl_c_stops_sections_and_families_at_once(o, analysis):
    calls = {
        # Each runs for minutes uninterrupted.
        "section": lambda: B.poincare_section(0.0, -1.0, orbits=2000, crossings=5000),
        "family": lambda: B.continue_orbit(o, (-1.5, 1e6), max_orbits=100_000, max_step=1e-4),
    }
    timer = interrupt_after(0.3)
    t0 = time.monotonic()
    try:
        with pytest.raises(KeyboardInterrupt):
            calls[analysis]()
    finally:
        timer.cancel()
    # The signal is seen within 50 ms and the work stops at its next integration step; 5 s is a
    # bound for a loaded machine, far below the minutes the call would run.
    assert time.monotonic() - t0 < 5
