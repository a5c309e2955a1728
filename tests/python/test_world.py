# SPDX-License-Identifier: BSL-1.0
"""World: many bodies stepped from Python, against the exact reference (every
pair of posed bodies tested in rational arithmetic, exact_reference.py),
with events, witnesses, threads, coherence and a translated copy of the
scene checked against each other; and every refused input leaving the world
as it was."""

import math

import numpy as np
import pytest
import shapely.geometry

import influence2d
import exact_reference
from conftest import dyadic, star_polygon, tiling_layer


def shapes_of(rng):
    """Stars, a unit square (squares on a unit grid touch exactly), a star
    with a hole, and a multipolygon of two stars."""
    square = shapely.geometry.box(0, 0, 1, 1)
    holed = shapely.geometry.Polygon(
        [(-1.5, -1.5), (1.5, -1.5), (1.5, 1.5), (-1.5, 1.5)],
        [list(reversed(star_polygon(rng, 7, radius=1.0).exterior.coords))])
    two = shapely.geometry.MultiPolygon([star_polygon(rng, 6, radius=0.6, center=(-0.8, 0.0)),
                                         star_polygon(rng, 5, radius=0.6, center=(0.9, 0.2))])
    assert holed.is_valid and two.is_valid
    return [star_polygon(rng, 9, radius=1.0), star_polygon(rng, 12, radius=0.7), square, holed, two,
            star_polygon(rng, 4, radius=0.5)]


class Scene:
    """Bodies (shape, pose, fixed) and their steps: each step a list of
    ("move", ids, poses), ("remove", ids) or ("add", shapes, poses, fixed)."""

    def __init__(self, shapes, shape_of, poses, fixed, steps):
        self.shapes, self.shape_of, self.poses, self.fixed, self.steps = shapes, shape_of, poses, fixed, steps


def random_scene(rng, count=22, steps=7, turn=True):
    shapes = shapes_of(rng)
    shape_of = [rng.randrange(len(shapes)) for _ in range(count)]
    # Unit squares on the unit grid (touching exactly), the others anywhere
    # in the box; a few bodies fixed.
    poses = []
    for s in shape_of:
        if s == 2:
            poses.append((float(rng.randrange(6)), float(rng.randrange(6)), 0.0))
        else:
            poses.append((dyadic(rng.uniform(0, 6)), dyadic(rng.uniform(0, 6)),
                          dyadic(rng.uniform(-3, 3)) if turn else 0.0))
    fixed = [k % 7 == 0 for k in range(count)]
    movable = [not f for f in fixed]
    kinds = list(shape_of)
    plan = []
    alive = list(range(count))
    total = count
    for step in range(steps):
        actions = []
        moved = rng.sample([b for b in alive if movable[b]], rng.randrange(1, 8))
        new = []
        for b in moved:
            d = (dyadic(rng.uniform(-0.3, 0.3)), dyadic(rng.uniform(-0.3, 0.3)))
            new.append((d, dyadic(rng.uniform(-0.2, 0.2)) if turn and kinds[b] != 2 else 0.0))
        actions.append(("move", moved, new))
        if step == 3:
            gone = rng.sample(alive, 2)
            alive = [b for b in alive if b not in gone]
            actions.append(("remove", gone))
        if step == 4:
            s = rng.randrange(len(shapes))
            actions.append(("add", [s], [(dyadic(rng.uniform(0, 6)), dyadic(rng.uniform(0, 6)), 0.0)], [False]))
            alive.append(total)
            movable.append(True)
            kinds.append(s)
            total += 1
        plan.append(actions)
    return Scene(shapes, shape_of, poses, fixed, plan)


def play(scene, world, record):
    """Runs the scene in `world`; calls record(world, state) after each step,
    state the bodies' exact poses, shapes, fixed flags and liveness."""
    shape_ids = world.add_shapes(scene.shapes)
    assert list(shape_ids) == list(range(len(scene.shapes)))
    state = {"poses": list(scene.poses), "shape": list(scene.shape_of), "fixed": list(scene.fixed),
             "alive": [True] * len(scene.poses)}
    ids = world.add_bodies(scene.shape_of, np.array(scene.poses), np.array(scene.fixed))
    assert list(ids) == list(range(len(scene.poses)))
    world.step()
    record(world, state)
    for actions in scene.steps:
        for action in actions:
            if action[0] == "move":
                _, bodies, deltas = action
                poses = []
                for b, ((dx, dy), dt) in zip(bodies, deltas):
                    tx, ty, th = state["poses"][b]
                    state["poses"][b] = (tx + dx, ty + dy, th + dt)
                    poses.append(state["poses"][b])
                world.move(bodies, np.array(poses, dtype=np.float64).reshape(-1, 3))
            elif action[0] == "remove":
                world.remove(action[1])
                for b in action[1]:
                    state["alive"][b] = False
            else:
                _, shapes, poses, fixed = action
                got = world.add_bodies(shapes, np.array(poses), np.array(fixed))
                assert list(got) == list(range(len(state["poses"]), len(state["poses"]) + len(shapes)))
                state["poses"] += poses
                state["shape"] += shapes
                state["fixed"] += fixed
                state["alive"] += [True] * len(shapes)
        world.step()
        record(world, state)


def reach(geom):
    """The largest distance of a vertex from the shape's own origin."""
    return max(math.hypot(x, y) for r in exact_reference.rings_of(geom) for x, y in r[0])


def reference_contacts(scene, state):
    """Every pair (i < j) of live bodies, not both fixed, whose exactly posed
    closed regions meet."""
    rings = [exact_reference.oriented(exact_reference.rings_of(g)) for g in scene.shapes]
    radius = [reach(g) for g in scene.shapes]
    posed = {}
    out = []
    n = len(state["poses"])
    for i in range(n):
        for j in range(i + 1, n):
            if not (state["alive"][i] and state["alive"][j]) or (state["fixed"][i] and state["fixed"][j]):
                continue
            (xi, yi, _), (xj, yj, _) = state["poses"][i], state["poses"][j]
            # Posed vertices lie within the shape's reach of the pose's
            # translation (a turn keeps lengths; c and s are within 2^-52
            # of a unit vector): a pair farther apart than both reaches
            # and a margin is apart.
            if math.hypot(xi - xj, yi - yj) > radius[state["shape"][i]] + radius[state["shape"][j]] + 1e-6:
                continue
            for k in (i, j):
                if k not in posed:
                    posed[k] = exact_reference.posed(rings[state["shape"][k]], state["poses"][k])
            if exact_reference.regions_meet(posed[i], posed[j]):
                out.append((i, j))
    return out


def as_pairs(array):
    return [tuple(int(v) for v in row) for row in array]


@pytest.mark.parametrize("number_type", ["certified", "exact"])
def test_contacts_match_the_exact_reference_at_every_step(rng, number_type):
    scene = random_scene(rng)
    met = []

    def record(world, state):
        got = as_pairs(world.contacts)
        assert got == sorted(got)
        assert got == reference_contacts(scene, state), f"step {len(met)}"
        met.append(len(got))

    play(scene, influence2d.World(number_type), record)
    # Not vacuous: contacts at every step, touching squares among them.
    assert len(met) == len(scene.steps) + 1 and min(met) > 0


def test_double_matches_the_reference_where_posing_is_exact(rng):
    # Unturned bodies on a dyadic grid: posing is exact in double, so double
    # must give the exact answers, touching pairs included.
    scene = random_scene(rng, turn=False)
    play(scene, influence2d.World("double"),
         lambda w, state: (as_pairs(w.contacts) == reference_contacts(scene, state)) or pytest.fail("differs"))


def run_all(scene, **options):
    """Contacts, events, witnesses and statistics after each step."""
    out = []

    def record(world, state):
        out.append((world.contacts.copy(), world.events(), world.witnesses() if options.get("witness") else None))

    world = influence2d.World(**options)
    play(scene, world, record)
    return out, world.statistics


def test_events_are_the_difference_of_consecutive_contacts(rng):
    steps, _ = run_all(random_scene(rng))
    before = set()
    changes = 0
    for contacts, (pairs, begins), _ in steps:
        now = set(as_pairs(contacts))
        expected = sorted([(p, True) for p in now - before] + [(p, False) for p in before - now])
        assert sorted(zip(as_pairs(pairs), (bool(b) for b in begins))) == expected
        assert as_pairs(pairs) == sorted(as_pairs(pairs))
        changes += len(expected)
        before = now
    assert changes > len(steps)


def test_witnesses_show_each_contact(rng):
    scene = random_scene(rng)
    shown = {"edge": 0, "vertex": 0}

    def record(world, state):
        wit = world.witnesses()
        contacts = as_pairs(world.contacts)
        assert all(len(v) == len(contacts) for v in wit.values())
        for k, (i, j) in enumerate(contacts):
            # Each body's rings in input order (the witnesses' numbering),
            # posed exactly.
            rings = {b: [r for r, _ in exact_reference.rings_of(scene.shapes[state["shape"][b]])] for b in (i, j)}
            posed = {b: exact_reference.posed(rings[b], state["poses"][b]) for b in (i, j)}
            oriented = {b: exact_reference.posed(exact_reference.oriented(
                exact_reference.rings_of(scene.shapes[state["shape"][b]])), state["poses"][b]) for b in (i, j)}

            def at(b, index):
                for ring in posed[b]:
                    if index < len(ring):
                        return ring, index
                    index -= len(ring)
                raise AssertionError(f"index {index} beyond body {b}'s vertices")

            kinds = (str(wit["first_kind"][k]), str(wit["second_kind"][k]))
            index = (int(wit["first_index"][k]), int(wit["second_index"][k]))
            if kinds == ("edge", "edge"):
                (ra, ia), (rb, ib) = at(i, index[0]), at(j, index[1])
                assert exact_reference.segments_meet(ra[ia], ra[(ia + 1) % len(ra)], rb[ib], rb[(ib + 1) % len(rb)])
                shown["edge"] += 1
            elif kinds == ("vertex", "interior"):
                ring, v = at(i, index[0])
                assert exact_reference.contains(oriented[j], ring[v]) and index[1] == -1
                shown["vertex"] += 1
            elif kinds == ("interior", "vertex"):
                ring, v = at(j, index[1])
                assert exact_reference.contains(oriented[i], ring[v]) and index[0] == -1
                shown["vertex"] += 1
            else:
                raise AssertionError(f"contact {(i, j)}: witness kinds {kinds}")

    play(scene, influence2d.World(witness=True), record)
    assert shown["edge"] > 0


def test_threads_and_coherence_change_nothing(rng):
    scene = random_scene(rng)
    serial, stats = run_all(scene, witness=True)
    assert stats["witness_hits"] > 0  # coherence was used
    for options in ({"threads": 2}, {"threads": 0}, {"coherence": False}):
        other, _ = run_all(scene, witness=True, **options)
        for (c0, (p0, b0), w0), (c1, (p1, b1), w1) in zip(serial, other):
            assert np.array_equal(c0, c1) and np.array_equal(p0, p1) and np.array_equal(b0, b1)
            # (Without coherence a contact may be shown by other features.)
            assert "coherence" in options or all(np.array_equal(w0[key], w1[key]) for key in w0), options


def test_translating_the_whole_scene_changes_no_contact(rng):
    # Every posed coordinate moves by the same dyadic offset, exactly: the
    # exact contacts are the same.
    scene = random_scene(rng)
    moved = Scene(scene.shapes, scene.shape_of, [(tx + 96.5, ty - 40.25, th) for tx, ty, th in scene.poses],
                  scene.fixed,
                  [[(a[0], a[1], [(x + 96.5, y - 40.25, t) for x, y, t in a[2]], a[3]) if a[0] == "add" else a
                    for a in actions] for actions in scene.steps])
    first, _ = run_all(scene)
    second, _ = run_all(moved)
    assert [as_pairs(c) for c, _, _ in first] == [as_pairs(c) for c, _, _ in second]


def test_within_counts_pairs_near_enough():
    w = influence2d.World(within=0.5)
    s = w.add_shape("POLYGON ((0 0, 1 0, 1 1, 0 1, 0 0))")
    w.add_bodies([s, s, s], [[0.0, 0.0, 0.0], [1.5, 0.0, 0.0], [3.0625, 0.0, 0.0]])
    assert as_pairs(w.step()) == [(0, 1)]  # 0.5 apart counts, 0.5625 does not
    w.move([2], [[3.0, 0.0, 0.0]])
    assert as_pairs(w.step()) == [(0, 1), (1, 2)]
    w.move([2], [[3.0000001, 0.0, 0.0]])
    assert as_pairs(w.step()) == [(0, 1)]


def test_fixed_bodies_are_not_tested_against_each_other():
    w = influence2d.World()
    s = w.add_shape("POLYGON ((0 0, 1 0, 1 1, 0 1, 0 0))")
    w.add_bodies([s, s], [[0.0, 0.0, 0.0], [0.5, 0.0, 0.0]], fixed=True)
    w.add_body(s, (0.25, 0.5, 0.0))
    assert as_pairs(w.step()) == [(0, 2), (1, 2)]


def test_refused_input_leaves_the_world_as_it_was():
    w = influence2d.World(witness=True)
    s = w.add_shape("POLYGON ((0 0, 1 0, 1 1, 0 1, 0 0))")
    w.add_bodies([s, s, s], [[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [5.0, 0.0, 0.0]])
    w.remove([2])
    before = as_pairs(w.step())
    stats = w.statistics
    bad_calls = [
        (lambda: w.move([0, 0], [[0.5, 0.0, 0.0], [0.5, 0.0, 0.0]]), "bodies[1] is 0, listed already at [0]"),
        (lambda: w.move([0, 2], [[0.5, 0.0, 0.0], [0.5, 0.0, 0.0]]), "bodies[1] is 2: the body was removed"),
        (lambda: w.move([0, 9], [[0.5, 0.0, 0.0], [0.5, 0.0, 0.0]]), "bodies[1] is 9: no body 9 (there are 3)"),
        (lambda: w.move([0, -1], [[0.5, 0.0, 0.0], [0.5, 0.0, 0.0]]), "bodies[1] is -1"),
        (lambda: w.move([0, 1], [[0.5, 0.0, 0.0], [0.5, 0.0, np.nan]]), "poses[1, 2] (theta) is nan"),
        (lambda: w.move([0, 1], [[0.5, 0.0, 0.0]]), "2 bodies for 1 poses"),
        (lambda: w.move([0.0, 1.0], [[0.5, 0.0, 0.0], [0.5, 0.0, 0.0]]), "expected integer ids"),
        (lambda: w.move([[0, 1]], [[0.5, 0.0, 0.0], [0.5, 0.0, 0.0]]), "expected a 1-D array of ids"),
        (lambda: w.move([0], [[0.5, 0.0]]), "expected an array of shape (n, 3)"),
        (lambda: w.remove([1, 2]), "bodies[1] is 2: the body was removed"),
        (lambda: w.add_bodies([0, 1], [[0.0, 0.0, 0.0], [0.0, 0.0, 0.0]]), "shapes[1] is 1: no shape 1"),
        (lambda: w.add_bodies([0, 0], [[0.0, 0.0, 0.0], [0.0, np.inf, 0.0]]), "poses[1, 1] (ty) is inf"),
        (lambda: w.add_bodies([0, 0], [[0.0, 0.0, 0.0]]), "2 shape ids for 1 poses"),
        (lambda: w.add_bodies([0], [[0.0, 0.0, 0.0]], fixed=[1]), "fixed: expected a bool"),
        (lambda: w.add_bodies([0], [[0.0, 0.0, 0.0]], fixed="yes"), "fixed is 'yes': expected True or False"),
        (lambda: w.add_bodies([0], [[0.0, 0.0, 0.0]], fixed=np.array([True, False])), "fixed: expected 1 flags"),
        (lambda: w.add_shapes(["POLYGON ((0 0, 1 0, 0 1, 0 0))", "POLYGON ((0 0, 1 0))"]), "shapes[1]"),
        (lambda: w.add_shape("POLYGON ((0 0, nan 0, 0 1, 0 0))"), "shape"),
    ]
    for call, message in bad_calls:
        with pytest.raises(influence2d.InvalidInput) as e:
            call()
        assert isinstance(e.value, ValueError)
        assert message in str(e.value), (message, str(e.value))
    assert len(w) == 3 and w.shape_count == 1 and list(w.alive) == [True, True, False]
    assert w.statistics == stats
    assert as_pairs(w.step()) == before  # nothing moved: every pair carried
    assert w.statistics["candidates"] == stats["candidates"]


@pytest.mark.parametrize("options, message", [
    ({"number_type": "float"}, "number_type 'float'"),
    ({"within": -1.0}, "distance"),
    ({"within": float("nan")}, "distance"),
    ({"within": "near"}, "within: expected a number"),
    ({"threads": -1}, "threads is -1"),
    ({"threads": 1.5}, "threads is 1.5: expected an integer"),
    ({"threads": 2**64}, f"threads is {2**64}: expected an integer from"),
    ({"number_type": None}, "number_type is None: expected a name"),
    ({"witness": "no"}, "witness is 'no': expected True or False"),
    ({"coherence": None}, "coherence is None: expected True or False"),
])
def test_refused_options(options, message):
    with pytest.raises(influence2d.InvalidInput, match=message):
        influence2d.World(**options)


def test_witnesses_need_the_option():
    w = influence2d.World()
    w.step()
    with pytest.raises(influence2d.InvalidInput, match="witness=True"):
        w.witnesses()


# --- world_contacts: a table of steps ------------------------------------------

def steps_table(rng, bodies=18, steps=24, turn=True):
    """A table of steps as the tool reads STEPS.csv: bodies of the shapes of
    shapes_of with ids 1000 + 7k, joining at their own steps, some fixed;
    each step moves a few free bodies a little (some in several steps in a
    row, so that contacts persist). Step numbers are sparse."""
    shapes = shapes_of(rng)
    kind = [rng.randrange(len(shapes)) for _ in range(bodies)]
    joins = sorted(rng.randrange(steps // 3) for _ in range(bodies))
    fixed = [k % 6 == 0 for k in range(bodies)]
    pose = {}
    rows = []
    for s in range(steps):
        number = 3 * s + (s % 2)
        present = [k for k in range(bodies) if joins[k] <= s]
        free = [k for k in present if not fixed[k] and k in pose]
        movers = set(rng.sample(free, min(5, len(free))))
        for k in present:
            if k not in pose:
                pose[k] = (float(rng.randrange(6)), float(rng.randrange(6)), 0.0) if kind[k] == 2 else \
                    (dyadic(rng.uniform(0, 6)), dyadic(rng.uniform(0, 6)), dyadic(rng.uniform(-3, 3)) if turn else 0.0)
            elif k in movers:
                tx, ty, th = pose[k]
                pose[k] = (tx + dyadic(rng.uniform(-0.25, 0.25)), ty + dyadic(rng.uniform(-0.25, 0.25)),
                           th + (dyadic(rng.uniform(-0.1, 0.1)) if turn and kind[k] != 2 else 0.0))
            else:
                continue
            rows.append((number, 1000 + 7 * k, kind[k], *pose[k], int(fixed[k])))
    rng.shuffle(rows)  # (the rows of a step in any order)
    rows.sort(key=lambda r: r[0])
    import pandas as pd
    return shapes, pd.DataFrame(rows, columns=["step", "body", "shape", "tx", "ty", "theta", "fixed"])


def tool_contacts(tool, tmp_path, shapes, table, *options):
    """`influence2d world` on the same shapes and steps, its CONTACTS.csv as
    a DataFrame."""
    import pandas as pd
    from conftest import run_tool
    (tmp_path / "shapes.wkt").write_text("".join(g.wkt + "\n" for g in shapes))
    with open(tmp_path / "steps.csv", "w") as f:
        f.write("step,body,shape,tx,ty,theta,fixed\n")
        for r in table.itertuples(index=False):
            f.write(f"{r.step},{r.body},{r.shape},{float(r.tx)!r},{float(r.ty)!r},{float(r.theta)!r},{r.fixed}\n")
    run_tool(tool, "world", "--shapes", tmp_path / "shapes.wkt", "--steps", tmp_path / "steps.csv", *options,
             "--out", tmp_path / "contacts.csv")
    return pd.read_csv(tmp_path / "contacts.csv")


@pytest.mark.parametrize("number_type", ["certified", "exact", "double"])
def test_world_contacts_is_the_tool_on_the_same_steps(tool, tmp_path, rng, number_type):
    import pandas.testing
    shapes, table = steps_table(rng)
    for events in (False, True):
        got = influence2d.world_contacts(shapes, table, number_type=number_type, events=events)
        want = tool_contacts(tool, tmp_path, shapes, table, "--number-type", number_type,
                             *(["--events"] if events else []))
        pandas.testing.assert_frame_equal(got, want, check_dtype=False)
        assert len(got) > 2 * table["step"].nunique()  # many contacts (or events), not a few


def test_world_contacts_answers_as_the_exact_reference(rng):
    shapes, table = steps_table(rng, steps=10)
    got = influence2d.world_contacts(shapes, table, within=0.0)
    scene = Scene(shapes, [], [], [], [])
    state = {"poses": [], "shape": [], "fixed": [], "alive": []}
    index = {}
    for number, rows in table.groupby("step", sort=True):
        for r in rows.itertuples(index=False):
            if r.body not in index:
                index[r.body] = len(state["poses"])
                state["poses"].append(None)
                state["shape"].append(r.shape)
                state["fixed"].append(bool(r.fixed))
                state["alive"].append(True)
            state["poses"][index[r.body]] = (r.tx, r.ty, r.theta)
        ids = {v: k for k, v in index.items()}
        want = sorted(tuple(sorted((ids[i], ids[j]))) for i, j in reference_contacts(scene, state))
        assert as_pairs(got[got["step"] == number][["a", "b"]].to_numpy()) == want, number


def test_world_contacts_of_no_steps():
    import pandas as pd
    got = influence2d.world_contacts(["POLYGON ((0 0, 1 0, 0 1, 0 0))"], pd.DataFrame(
        {c: np.zeros(0, dtype=np.int64 if c in ("step", "body", "shape") else float)
         for c in ("step", "body", "shape", "tx", "ty", "theta")}))
    assert list(got.columns) == ["step", "a", "b"] and len(got) == 0


def bad_table(change):
    import pandas as pd
    table = pd.DataFrame({"step": [0, 0, 1, 1], "body": [5, 6, 5, 6], "shape": [0, 0, 0, 0],
                          "tx": [0.0, 1.0, 0.5, 1.5], "ty": [0.0] * 4, "theta": [0.0] * 4, "fixed": [0, 0, 0, 0]})
    change(table)
    return table


@pytest.mark.parametrize("change, message", [
    (lambda t: t.__setitem__("step", [0, 1, 0, 1]), "steps, row 2: step 0 after step 1: steps must not go back"),
    (lambda t: t.__setitem__("body", [5, 6, 5, 5]), "steps, row 3: body 5 is listed twice in step 1 (also row 2)"),
    (lambda t: t.__setitem__("shape", [0, 0, 0, 1]), "steps, row 3, column shape: no shape 1 (there are 1)"),
    (lambda t: t.__setitem__("fixed", [0, 0, 1, 0]), "steps, row 2, column fixed: body 5 has fixed False since row 0"),
    (lambda t: t.__setitem__("fixed", [0, 2, 0, 0]), "steps, row 1, column fixed: 2 is not 0 or 1"),
    (lambda t: t.__setitem__("tx", [0.0, np.nan, 0.0, 0.0]), "steps, row 1, column tx: nan is not a finite number"),
    (lambda t: t.__setitem__("theta", [0.0, 0.0, 0.0, np.inf]), "steps, row 3, column theta: inf"),
    (lambda t: t.__setitem__("body", [5.0, 6.0, 5.0, 6.0]), "steps, column body: expected integers, got dtype float64"),
    (lambda t: t.__setitem__("step", [0, 0, -1, 1]), "steps, row 2, column step: -1 is not an integer from 0"),
    (lambda t: t.__setitem__("ty", ["a", "b", "c", "d"]), "steps, column ty: expected numbers"),
    (lambda t: t.drop(columns="theta", inplace=True), "steps: no column 'theta'"),
])
def test_world_contacts_refuses_a_bad_table_naming_the_row(change, message):
    with pytest.raises(influence2d.InvalidInput) as e:
        influence2d.world_contacts(["POLYGON ((0 0, 1 0, 1 1, 0 1, 0 0))"], bad_table(change))
    assert message in str(e.value), str(e.value)


def test_statistics_count_the_pairs_answered_in_exact_rationals():
    # Unit squares turned by 0.3, the second at (cos 0.3, sin 0.3): its left
    # edge lies exactly on the first's right edge, which double cannot
    # settle; certified answers the pair again in exact rationals.
    c, s = math.cos(0.3), math.sin(0.3)
    poses = np.array([[0.0, 0.0, 0.3], [c, s, 0.3], [4 * c, 4 * s, 0.3]])
    for number_type, exact_pairs in (("certified", 1), ("exact", 0), ("double", 0)):
        w = influence2d.World(number_type)
        w.add_bodies([w.add_shape("POLYGON ((0 0, 1 0, 1 1, 0 1, 0 0))")] * 3, poses)
        if number_type != "double":
            assert as_pairs(w.step()) == [(0, 1)]
        else:
            w.step()
        assert w.statistics["exact_pairs"] == exact_pairs, number_type


@pytest.mark.parametrize("number_type", ["certified", "exact"])
def test_a_tiling_slid_apart_and_back_matches_the_exact_reference(rng, number_type):
    # Each cell of a tiling (borders shared to the bit, holes with islands
    # touching them or one grid step inside) a body at its place; at each
    # step some bodies slide by a few grid steps (1/64) and some come back
    # to their place, where they touch their neighbours again exactly, or
    # stand exactly 1/64 from them. Every step, with and without coherence,
    # within 0 and 1/64, against the exact distance of every pair.
    shapes = tiling_layer(rng, 4, 4)
    boxes = [g.bounds for g in shapes]
    fixed = [rng.random() < 0.25 for _ in shapes]
    plan, at = [], [(0.0, 0.0)] * len(shapes)
    for _ in range(8):
        moved = [k for k in range(len(shapes)) if not fixed[k] and rng.random() < 0.5]
        for k in moved:
            at[k] = (0.0, 0.0) if rng.random() < 0.3 else (at[k][0] + rng.randint(-3, 3) / 64,
                                                             at[k][1] + rng.randint(-3, 3) / 64)
        plan.append((moved, [at[k] for k in moved], list(at)))
    for within in [0.0, 1 / 64]:
        want = []
        for _, _, poses in plan:
            pairs = []
            for i in range(len(shapes)):
                for j in range(i + 1, len(shapes)):
                    if fixed[i] and fixed[j]:
                        continue
                    (xi, yi), (xj, yj) = poses[i], poses[j]
                    a, b = boxes[i], boxes[j]
                    # (Boxes farther apart than the distance, with room for
                    # these sums' rounding, hold bodies farther apart.)
                    reach = within + 1e-9
                    if (a[0] + xi > b[2] + xj + reach or b[0] + xj > a[2] + xi + reach
                            or a[1] + yi > b[3] + yj + reach or b[1] + yj > a[3] + yi + reach):
                        continue
                    if exact_reference.squared_distance(shapes[i], shapes[j], (xj, yj, 0.0), within,
                                                        a_pose=(xi, yi, 0.0)) is not None:
                        pairs.append((i, j))
            want.append(pairs)
        # Not vacuous: touching neighbours at every step.
        assert min(len(p) for p in want) > 0
        for coherence in [True, False]:
            world = influence2d.World(number_type, within=within, coherence=coherence)
            ids = world.add_bodies(world.add_shapes(shapes), np.zeros((len(shapes), 3)), fixed=np.array(fixed))
            assert ids.tolist() == list(range(len(shapes)))
            world.step()
            for step, (moved, poses, _) in enumerate(plan):
                if moved:
                    world.move(moved, np.array([[x, y, 0.0] for x, y in poses]))
                assert as_pairs(world.step()) == want[step], f"within {within}, coherence {coherence}, step {step}"
