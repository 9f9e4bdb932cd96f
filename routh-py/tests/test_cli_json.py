"""One JSON schema for Rust, the command line and Python: what `routh orbit --json` and
`routh orbits --json` print is read by `from_json` into PeriodicOrbit and OrbitFamily objects
with the same numbers, bit for bit; the bare serde text of the Rust values is read too.

The CLI's output is kept in tests/data/ (routh-cli/tests/orbit.rs,
`the_python_tests_data_is_what_the_cli_prints`, names the commands and checks that the CLI still
prints that shape; `ROUTH_BLESS=1 cargo test -p routh-cli --test orbit` writes the files again).
When a `routh` binary is at hand (the environment variable ROUTH_BIN, `routh` on the PATH, or one
built in the workspace's target/) it is also run live."""

import json
import math
import os
import pathlib
import shutil
import subprocess

import numpy as np
import pytest

import routh
from conftest import ROOT

DATA = pathlib.Path(__file__).resolve().parent / "data"
BODY = ROOT / "routh-cli" / "tests" / "models" / "swinging_body.toml"


def load(name):
    return (DATA / name).read_text()


def same_orbit(o, d):
    """The Python orbit `o` has the numbers of the JSON object `d`, bit for bit."""
    for name in ("period", "energy", "p_psi", "precession", "body_turn", "stability_index",
                 "amplitude"):
        assert getattr(o, name) == d[name], name
    assert o.degenerate is d["degenerate"]
    np.testing.assert_array_equal(o.omega0, np.array(d["omega0"], dtype=float))
    np.testing.assert_array_equal(o.gamma0, np.array(d["gamma0"], dtype=float))
    mu = np.array([complex(re, im) for re, im in d["multipliers"]])
    np.testing.assert_array_equal(o.multipliers, mu)
    # Kinds and stabilities: the serde names (CamelCase) become the lower-case strings.
    assert o.stability == {"Elliptic": "elliptic", "Parabolic": "parabolic",
                           "Hyperbolic": "hyperbolic",
                           "InverseHyperbolic": "inverse_hyperbolic"}[d["stability"]]


KINDS = {"Fold": "fold", "BranchPoint": "branch_point", "PeriodDoubling": "period_doubling"}


def same_family(f, d):
    assert isinstance(f, routh.OrbitFamily)
    assert len(f.orbits) == len(d["orbits"]) and len(f.events) == len(d["events"])
    for o, od in zip(f.orbits, d["orbits"]):
        same_orbit(o, od)
    np.testing.assert_array_equal(f.energy, [od["energy"] for od in d["orbits"]])
    for e, ed in zip(f.events, d["events"]):
        assert e.kind == KINDS[ed["kind"]]
        assert e.energy == ed["energy"]
        same_orbit(e.orbit, ed["orbit"])
    assert (f.stop is None) == (d["stop"] is None)


def test_cli_orbit_json_reads_into_a_periodic_orbit():
    text = load("cli_orbit.json")
    doc = json.loads(text)
    assert doc["routh"] == "PeriodicOrbit" and doc["format"] == 1
    for o in (routh.PeriodicOrbit.from_json(text), routh.from_json(text)):
        assert isinstance(o, routh.PeriodicOrbit)
        same_orbit(o, doc)
    # The orbit's period is the pendulum's 4K(m)/ω₀ (the body of routh-cli/tests/orbit.rs).
    o = routh.from_json(text)
    m = 0.5 * (1.0 + o.energy / 1.5)  # sin²(θ_max/2), cos θ_max = −E/mgl
    a, g = 1.0, math.sqrt(1.0 - m)
    for _ in range(60):
        a, g = 0.5 * (a + g), math.sqrt(a * g)
    exact = 4 * (math.pi / (2 * a)) / math.sqrt(1.5)
    assert abs(o.period - exact) < 1e-8 * exact
    # Python writes it back as the same document (the CLI's key order aside).
    assert json.loads(o.to_json()) == doc


def test_cli_orbits_json_reads_into_families():
    text = load("cli_orbits.json")
    docs = json.loads(text)
    assert isinstance(docs, list) and len(docs) >= 2
    assert {d["origin"] for d in docs} >= {"lyapunov", "period_doubled"}
    for fams in (routh.from_json(text), routh.OrbitFamily.from_json(text)):
        assert isinstance(fams, list) and len(fams) == len(docs)
        for f, d in zip(fams, docs):
            same_family(f, d)
    # The steady motion of a Lyapunov family is a SteadyMotion document of its own.
    lyap = next(d for d in docs if d["origin"] == "lyapunov")
    s = routh.from_json(json.dumps(lyap["motion"]))
    assert isinstance(s, routh.SteadyMotion)
    np.testing.assert_array_equal(s.gamma, np.array(lyap["motion"]["gamma"], dtype=float))
    # A period-doubled family names its parent and the event it was born at.
    for d in docs:
        if d["origin"] == "period_doubled":
            parent = docs[d["parent"]]
            assert parent["events"][d["event"]]["kind"] == "PeriodDoubling"
    # One family of the array, by itself.
    f = routh.OrbitFamily.from_json(json.dumps(docs[0]))
    same_family(f, docs[0])
    with pytest.raises(routh.RouthError, match="not a PeriodicOrbit"):
        routh.PeriodicOrbit.from_json(text)


def test_cli_orbits_through_a_parameter_read_into_a_family():
    # `routh orbits --continue --parameter a=0.8..1.5`: an OrbitFamily document with the keys
    # parameter_name, parameter and event_parameter besides (ignored by from_json).
    text = load("cli_orbits_parameter.json")
    docs = json.loads(text)
    assert len(docs) == 1
    d = docs[0]
    assert d["origin"] == "continued" and d["parameter_name"] == "a"
    assert len(d["parameter"]) == len(d["orbits"]) and len(d["event_parameter"]) == len(d["events"])
    for fams in (routh.from_json(text), routh.OrbitFamily.from_json(text)):
        assert len(fams) == 1
        same_family(fams[0], d)
    f = routh.OrbitFamily.from_json(json.dumps(d))
    same_family(f, d)
    # At the fixed energy E = −1 each orbit is the pendulum of amplitude arccos(2/3) at ω₀² = 1.5/a.
    m = math.sin(math.acos(2 / 3) / 2) ** 2
    a_, g = 1.0, math.sqrt(1.0 - m)
    for _ in range(60):
        a_, g = 0.5 * (a_ + g), math.sqrt(a_ * g)
    for o, a in zip(f.orbits, d["parameter"]):
        assert abs(o.energy + 1.0) < 1e-9
        assert abs(o.period - 4 * (math.pi / (2 * a_)) / math.sqrt(1.5 / a)) < 1e-8


def test_bare_rust_serde_json_reads_when_the_class_is_named():
    # The serde text of the Rust values, without the two keys of the Python document.
    doc = json.loads(load("cli_orbit.json"))
    bare = {k: v for k, v in doc.items() if k not in ("routh", "format")}
    o = routh.PeriodicOrbit.from_json(json.dumps(bare))
    same_orbit(o, bare)
    fams = json.loads(load("cli_orbits.json"))
    keep = ("orbits", "events", "stop")
    bare = [{k: f[k] for k in keep} for f in fams]
    back = routh.OrbitFamily.from_json(json.dumps(bare))
    for f, d in zip(back, bare):
        same_family(f, d)
    ev = fams[0]["events"][0]
    e = routh.OrbitEvent.from_json(json.dumps(ev))
    assert e.kind == KINDS[ev["kind"]] and e.energy == ev["energy"]
    # Without the class, a bare text is not recognised; a broken one names what is missing.
    with pytest.raises(routh.RouthError, match="no \"routh\" key"):
        routh.from_json(json.dumps(bare[0]))
    broken = dict(json.loads(load("cli_orbit.json")))
    del broken["period"]
    with pytest.raises(routh.RouthError, match="period"):
        routh.from_json(json.dumps(broken))


def test_the_cli_orbit_is_the_python_orbit():
    # The same guess in Python gives the orbit the CLI printed (the same library).
    doc = json.loads(load("cli_orbit.json"))
    body = routh.Model.load(BODY)
    o = body.periodic_orbit([1.0, 0.0, 0.0], [0.0, 0.0, -1.0], 5.4)
    assert abs(o.period - doc["period"]) < 1e-9 * doc["period"]
    assert abs(o.energy - doc["energy"]) < 1e-12


def routh_bin():
    exe = os.environ.get("ROUTH_BIN") or shutil.which("routh")
    if exe is None:
        for profile in ("release", "debug"):
            p = ROOT / "target" / profile / "routh"
            if p.exists():
                return str(p)
    return exe


@pytest.mark.skipif(routh_bin() is None, reason="no routh binary (set ROUTH_BIN)")
def test_live_cli_json_reads():
    exe = routh_bin()
    out = subprocess.run(
        [exe, "orbit", str(BODY), "--omega", "1,0,0", "--gamma", "0,0,-1", "--period", "5.4",
         "--json"], capture_output=True, text=True, check=True).stdout
    same_orbit(routh.PeriodicOrbit.from_json(out), json.loads(out))
    out = subprocess.run(
        [exe, "orbits", str(BODY), "--continue", "--omega", "1,0,0", "--gamma", "0,0,-1",
         "--period", "5.4", "--energy=-1.2..-0.9", "--json"],
        capture_output=True, text=True, check=True).stdout
    for f, d in zip(routh.from_json(out), json.loads(out)):
        same_family(f, d)
    # --switch: the family crossing at the branch point of the swings, read as any family.
    branching = ROOT / "routh-cli" / "tests" / "models" / "branching_body.toml"
    out = subprocess.run(
        [exe, "orbits", str(branching), "-p", "0", "--mode", "0", "--gamma", "0,0,-1",
         "--max-orbits", "30", "--switch", "--json"],
        capture_output=True, text=True, check=True).stdout
    docs = json.loads(out)
    assert [d["origin"] for d in docs] == ["lyapunov", "switched"]
    assert docs[0]["events"][docs[1]["event"]]["kind"] == "BranchPoint"
    for f, d in zip(routh.OrbitFamily.from_json(out), docs):
        same_family(f, d)
