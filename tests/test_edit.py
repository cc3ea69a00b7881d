"""The Task-Semantic Scene Editing Agent (issue 11): the paper's example made executable offline
on a generated two-floor office (the oracle does it with the variant, not without), each of the
eight tools alone with its errors, variants applied and reverted byte for byte, validated, and
the CLI end to end."""

from __future__ import annotations

import hashlib
import json
import shutil
import sys
from pathlib import Path
from typing import Any

import numpy as np
import pytest
from typer.testing import CliRunner

from mansion.building import generate_building
from mansion.cli import app
from mansion.edit import EditSpec, SceneTools, Workspace, edit_building, search_assets, sentence_embedder
from mansion.edit.surfaces import SETTLE
from mansion.edit.variants import apply_variant, list_variants, load_variant, patch_house, revert_variant
from mansion.exceptions import (
    ContainerClosedError,
    EditError,
    IncompatibleReceptacleError,
    InvalidInputError,
    SurfaceFullError,
    UnknownObjectError,
)
from mansion.placement.assets import database
from mansion.placement.check import footprint
from mansion.scene import write_scenes
from mansion.scene.house import house_text
from mansion.scene.validate import validate_path
from mansion.sim import BuildingEnv
from mansion.sim.agents import OracleAgent
from mansion.sim.evaluate import run_task

runner = CliRunner()

PAPER = {
    "text": "I need a task where the agent starts in the 1st-floor lobby, grabs a snack from the 2nd-floor "
            "table, gets a cold drink from the 2nd-floor fridge, and brings them to the 1st-floor sofa",
    "start": {"floor": 0, "room": "lobby"},
    "fetch": [{"object_type": "Apple", "floor": 1, "on": "DiningTable", "in": None},
              {"object_type": "WineBottle", "floor": 1, "on": None, "in": "Fridge"}],
    "deliver": {"floor": 0, "on": "Sofa"},
}


@pytest.fixture(scope="session")
def office(tmp_path_factory: pytest.TempPathFactory) -> Path:
    """Two floors: a lobby with sofas below, a staff kitchen (dining table, fridge) above."""
    root = tmp_path_factory.mktemp("edit-office")
    b = generate_building("a two-storey office with a staff kitchen on the top floor", floors=2, seed=4)
    write_scenes(b, root / "scenes")
    return root


def _copy(office: Path, tmp_path: Path) -> Path:
    out = tmp_path / "office"
    shutil.copytree(office / "scenes", out / "scenes")
    return out


def _digests(root: Path) -> dict[str, str]:
    return {p.name: hashlib.sha256(p.read_bytes()).hexdigest() for p in sorted((root / "scenes").glob("*.json"))}


@pytest.fixture()
def tools(office: Path) -> SceneTools:
    return SceneTools(Workspace(office))


def _kitchen(tools: SceneTools, kind: str) -> str:
    return next(i.id for i in tools.ws.of_type(1, kind) if i.room == "staff_kitchen")


# -- the paper's example --------------------------------------------------------------------------
@pytest.fixture(scope="session")
def paper_variant(office: Path) -> Any:
    before = _digests(office)
    result = edit_building(office, EditSpec.model_validate(PAPER), name="snack-and-drink")
    assert _digests(office) == before, "editing never changes the base building"
    return result


def test_paper_example_is_provisioned_and_saved(office: Path, paper_variant: Any) -> None:
    r = paper_variant
    assert r.ok, r.failed
    assert r.variant == office / "variants" / "snack-and-drink"
    apple, wine = r.task.targets
    assert (apple.object_type, apple.floor, apple.receptacle_type) == ("Apple", 1, "DiningTable")
    assert (wine.object_type, wine.floor, wine.receptacle_type) == ("WineBottle", 1, "Fridge")
    assert (r.task.destination.floor, r.task.destination.receptacle_type) == (0, "Sofa")
    assert r.task.start.floor == 0 and r.task.start.room == "lobby"
    # the lobby's sofa: the one in the start room comes first
    assert r.task.destination.room == "lobby"
    kinds = [line.kind for line in r.log.lines]
    assert kinds.count("precondition") == 6 and "edit" in kinds
    v = load_variant(office, "snack-and-drink")
    assert v.spec["fetch"][1]["in"] == "Fridge" and v.text == PAPER["text"]
    assert [p.floor for p in v.patch] == [1]
    added = {a.object["assetId"].split("_")[0] for a in v.patch[0].added}
    assert added >= {"Apple"} and any("Wine" in a.object["assetId"] for a in v.patch[0].added)
    assert v.patch[0].changed and v.patch[0].changed[0].set == {"openness": 1.0}  # the fridge, opened
    assert [x.name for x in list_variants(office)] == ["snack-and-drink"]


def test_oracle_completes_the_task_with_the_variant_and_fails_without(office: Path, paper_variant: Any) -> None:
    task = paper_variant.task
    with_variant = run_task(BuildingEnv(office, variant="snack-and-drink"), task, OracleAgent)
    assert with_variant.success and with_variant.retrieved and with_variant.floor_changes >= 2
    assert with_variant.steps * 2 + 10 == task.max_steps
    without = run_task(BuildingEnv(office), task, OracleAgent)
    assert not without.success and not without.retrieved


def test_every_edited_floor_validates(office: Path, paper_variant: Any) -> None:
    for p in load_variant(office, "snack-and-drink").patch:
        edited = paper_variant.variant / "scenes" / p.house
        found = validate_path(edited)
        assert [q for q in found if q.severity == "error"] == []
        assert sorted(q.rule for q in found) == sorted(q.rule for q in validate_path(office / "scenes" / p.house)), \
            "no new warning either"


def test_patch_replays_to_the_variant_scenes(office: Path, paper_variant: Any) -> None:
    v = load_variant(office, "snack-and-drink")
    for p in v.patch:
        base = json.loads((office / "scenes" / p.house).read_bytes())
        replayed = house_text(patch_house(base, p)).encode()
        assert replayed == (paper_variant.variant / "scenes" / p.house).read_bytes()


def test_editing_is_deterministic(office: Path, tmp_path: Path, paper_variant: Any) -> None:
    other = _copy(office, tmp_path)
    again = edit_building(other, EditSpec.model_validate(PAPER), name="snack-and-drink")
    assert again.ok
    for f in ("variant.json", "task.json", "scenes/floor_1.json"):
        assert (again.variant / f).read_bytes() == (paper_variant.variant / f).read_bytes()


def test_objects_already_there_are_found_not_added(office: Path, tmp_path: Path) -> None:
    root = _copy(office, tmp_path)
    ws = Workspace(root)
    table = next(i for i in ws.of_type(1, "DiningTable") if i.room == "staff_kitchen")
    there = ws.floor(1).objects[table.obj.children[0].id].props.object_type
    spec = {**PAPER, "fetch": [{"object_type": there, "floor": 1, "on": "DiningTable"}]}
    r = edit_building(root, EditSpec.model_validate(spec), name="found")
    assert r.ok, r.failed
    assert r.task.targets[0].object_id == table.obj.children[0].id
    assert not [e for e in r.edits if e.startswith("added")]
    assert any("is there" in line.text for line in r.log.lines)
    # applied, the provisioned objects of the paper's example are found the second time round
    first = edit_building(root, EditSpec.model_validate(PAPER), name="first")
    apply_variant(root, "first")
    second = edit_building(root, EditSpec.model_validate(PAPER), name="second")
    assert second.ok and not [e for e in second.edits if e.startswith("added")]
    assert [t.object_id for t in second.task.targets] == [t.object_id for t in first.task.targets]


def test_a_precondition_that_cannot_be_met_is_named(office: Path, tmp_path: Path) -> None:
    root = _copy(office, tmp_path)
    spec = {**PAPER, "fetch": [{"object_type": "Apple", "floor": 1, "on": "Bed"}]}
    r = edit_building(root, EditSpec.model_validate(spec), name="no-bed")
    assert not r.ok and r.variant is None
    assert "an Apple on a Bed on floor 1" in (r.failed or "") and "no Bed" in (r.failed or "")
    assert not (root / "variants" / "no-bed").exists()
    # the fridge takes no plain Bottle (AI2-THOR's receptacle database)
    spec = {**PAPER, "fetch": [{"object_type": "Bottle", "floor": 1, "in": "Fridge"}]}
    r = edit_building(root, EditSpec.model_validate(spec), name="bottle")
    assert not r.ok and "cannot take" in (r.failed or "")
    spec = {**PAPER, "fetch": [{"object_type": "Banana", "floor": 1, "on": "DiningTable"}]}
    r = edit_building(root, EditSpec.model_validate(spec), name="banana")
    assert not r.ok and "AI2-THOR has no object type 'Banana'" in (r.failed or "")
    spec = {**PAPER, "fetch": [{"object_type": "apple", "floor": 1, "on": "dining table"}]}
    r = edit_building(root, EditSpec.model_validate(spec), name="lower-case")
    assert r.ok and r.task.targets[0].object_type == "Apple" and r.task.targets[0].receptacle_type == "DiningTable"
    with pytest.raises(EditError, match="--spec"):
        edit_building(root, None, text="I need a task", name="x")


def test_spec_is_the_issue_format(tmp_path: Path) -> None:
    spec = EditSpec.model_validate(PAPER)
    assert json.loads(spec.model_dump_json()) == PAPER
    bad = tmp_path / "bad.json"
    bad.write_text(json.dumps({**PAPER, "fetch": [{"object_type": "Apple", "floor": 1, "on": "A", "in": "B"}]}))
    with pytest.raises(InvalidInputError, match="not both"):
        EditSpec.load(bad)


# -- the tools, one by one ----------------------------------------------------------------------
def test_check_path_across_floors(tools: SceneTools) -> None:
    r = tools.check_path(0, "lobby", 1, "Kitchen")
    assert r["ok"] and r["metres"] > 0 and r["cores"] and r["end"]["room"] == "staff_kitchen"
    assert any(ride.startswith(("TakeStairs", "UseElevator")) for ride in r["rides"])
    same = tools.check_path(1, "staff_kitchen", 1, "staff_kitchen")
    assert same["ok"] and same["cores"] == []
    with pytest.raises(UnknownObjectError, match="no room 'ballroom' on floor 0"):
        tools.check_path(0, "ballroom", 1, "staff_kitchen")
    with pytest.raises(UnknownObjectError, match="no floor 7"):
        tools.check_path(7, "lobby", 1, "staff_kitchen")


def test_search_assets_fuzzy_with_properties(tools: SceneTools) -> None:
    assert tools.search_assets("bottle of wine", 3)["assets"][0]["asset_id"] == "Wine_Bottle_1"
    apples = tools.search_assets("aple", 5, ["Pickupable"])["assets"]
    assert apples and all(a["object_type"] == "Apple" for a in apples)
    fridges = tools.search_assets("fridge", 10, ["Openable", "Receptacle"])["assets"]
    assert fridges and all({"Openable", "Receptacle"} <= set(a["properties"]) for a in fridges)
    assert not tools.search_assets("fridge", 10, ["Pickupable"])["assets"] or all(
        a["object_type"] != "Fridge" for a in tools.search_assets("fridge", 10, ["Pickupable"])["assets"])
    with pytest.raises(InvalidInputError):
        tools.search_assets("  ")
    with pytest.raises(InvalidInputError, match="no AI2-THOR asset"):
        tools.search_assets("apple", 3, ["Flying"])


class _ConceptEmbedder:
    """A stand-in embedding model with three meanings (a drink, a fruit, a seat): each word votes
    for its meaning, so "something to drink" and "wine bottle" are close though no letters match."""

    MEANING = {"drink": 0, "wine": 0, "beverage": 0, "apple": 1, "fruit": 1, "tomato": 1,
               "sofa": 2, "chair": 2, "seat": 2}

    def __init__(self) -> None:
        self.calls = 0

    def __call__(self, texts):
        self.calls += 1
        out = np.full((len(texts), 4), 0.0)
        for i, t in enumerate(texts):
            out[i, 3] = 0.1  # every text has a little of "other", so none is the zero vector
            for w in t.lower().split():
                if w in self.MEANING:
                    out[i, self.MEANING[w]] += 1.0
        return out


def test_search_assets_by_meaning_with_an_embedder(tools: SceneTools) -> None:
    lexical = tools.search_assets("something to drink", 3)["assets"]
    assert all(a["object_type"] != "WineBottle" for a in lexical)
    model = _ConceptEmbedder()
    semantic = SceneTools(tools.ws, embedder=model)
    found = semantic.search_assets("something to drink", 3)["assets"]
    assert found[0]["object_type"] == "WineBottle" and found[0]["score"] > 90
    seats = semantic.search_assets("a seat", 20, ["Receptacle"])["assets"]
    assert {a["object_type"] for a in seats[:3]} <= {"Sofa", "Chair", "ArmChair"}
    assert all("Receptacle" in a["properties"] for a in seats)
    assert model.calls == 3  # the catalogue once, then one call per query
    with pytest.raises(InvalidInputError, match="shape"):
        search_assets("apple", 3, embedder=lambda texts: np.zeros((1, 4)))


def test_semantic_search_without_its_extra_says_what_to_install(monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setitem(sys.modules, "sentence_transformers", None)
    with pytest.raises(InvalidInputError, match=r"mansion\[semantic\]"):
        sentence_embedder()


def test_list_objects_joins_the_asset_database(tools: SceneTools) -> None:
    kitchen = tools.list_objects(room="staff_kitchen")["objects"]
    fridge = next(o for o in kitchen if o["type"] == "Fridge")
    assert fridge["floor"] == 1 and fridge["receptacle"] and fridge["openable"] and fridge["open"] is False
    assert not fridge["pickupable"]
    small = [o for o in kitchen if o.get("parent")]
    assert small and all(o["pickupable"] for o in small)
    fridges = tools.list_objects(keyword_or_id="fridge")["objects"]
    assert {o["floor"] for o in fridges} == {0, 1} and all(o["type"] == "Fridge" for o in fridges)
    assert tools.list_objects(keyword_or_id=fridge["id"], floor=1)["objects"] == [fridge]
    with pytest.raises(UnknownObjectError):
        tools.list_objects(room="ballroom")


def test_check_surface_and_search_contents(tools: SceneTools) -> None:
    table = _kitchen(tools, "DiningTable")
    top = tools.check_surface(table, floor=1)["receptacles"][0]
    children = [c.id for c in tools.ws.floor(1).objects[table].obj.children]
    assert sorted(o["id"] for o in top["on_top"]) == sorted(children) and top["free_area_m2"] > 0
    fridge = tools.search_contents(_kitchen(tools, "Fridge"), floor=1)["receptacles"][0]
    assert fridge["inside"] == [] and fridge["open"] is False
    with pytest.raises(UnknownObjectError, match="no receptacle 'staff_kitchen|nothing'"):
        tools.check_surface("staff_kitchen|nothing", floor=1)
    item = children[0]
    if not tools.ws.floor(1).objects[item].props.receptacle:
        with pytest.raises(IncompatibleReceptacleError):
            tools.search_contents(item, floor=1)


def test_place_on_surface_packs_without_overlap(tools: SceneTools) -> None:
    table_id = _kitchen(tools, "DiningTable")
    st = tools.ws.floor(1)
    placed = []
    with pytest.raises(SurfaceFullError, match="no free spot on"):
        for _ in range(200):
            placed.append(tools.place_on_surface("Apple_1", table_id, floor=1)["placed"])
    assert len(placed) >= 3
    table = st.objects[table_id]
    top = table.obj.position.y + table.props.height / 2
    area = footprint(table.centre, table.props.width, table.props.depth, table.obj.rotation.y)
    prints = []
    for c in table.obj.children:
        info = st.objects[c.id]
        fp = footprint(info.centre, info.props.width, info.props.depth, c.rotation.y)
        assert fp.difference(area).area < 1e-9
        prints.append(fp)
        if c.id in placed:
            assert abs(c.position.y - info.props.height / 2 - top) <= SETTLE
    assert all(a.intersection(b).area < 1e-9 for i, a in enumerate(prints) for b in prints[i + 1:])
    assert tools.ws.reachable(1, table_id)
    n = len(table.obj.children)
    with pytest.raises(SurfaceFullError):
        tools.place_on_surface("Apple_1", table_id, floor=1)
    assert len(st.objects[table_id].obj.children) == n, "a refused placement changes nothing"


def test_place_in_container_closed_incompatible_and_open(tools: SceneTools) -> None:
    fridge = _kitchen(tools, "Fridge")
    with pytest.raises(ContainerClosedError, match="closed"):
        tools.place_in_container("Wine_Bottle_1", fridge, floor=1)
    with pytest.raises(IncompatibleReceptacleError, match="receptacle database"):
        tools.place_in_container("Bottle_1", fridge, floor=1, open=True)
    assert tools.edits == [] and not tools.ws.edited
    with pytest.raises(IncompatibleReceptacleError, match="use PlaceInContainer"):
        tools.place_on_surface("Wine_Bottle_1", fridge, floor=1)
    with pytest.raises(IncompatibleReceptacleError, match="use PlaceOnSurface"):
        tools.place_in_container("Apple_1", _kitchen(tools, "DiningTable"), floor=1)
    with pytest.raises(IncompatibleReceptacleError, match="cannot be picked up"):
        tools.place_on_surface("Fridge_1", _kitchen(tools, "DiningTable"), floor=1)
    sofa = tools.ws.of_type(0, "Sofa")[0].id
    with pytest.raises(IncompatibleReceptacleError, match="cannot take"):
        tools.place_on_surface("Wine_Bottle_1", sofa, floor=0)
    with pytest.raises(UnknownObjectError, match="did you mean"):
        tools.place_on_surface("Apple_1", "staff_kitchen|tabel", floor=1)
    with pytest.raises(UnknownObjectError, match="neither an AI2-THOR asset"):
        tools.place_on_surface("Apple_999", _kitchen(tools, "DiningTable"), floor=1)
    r = tools.place_in_container("Wine_Bottle_1", fridge, floor=1, open=True)
    st = tools.ws.floor(1)
    info, box = st.objects[r["placed"]], st.objects[fridge]
    assert r["opened"] and st.is_open(fridge) and st.inside(info) is None
    assert info.obj.position.y - info.props.height / 2 < box.obj.position.y + box.props.height / 2 - SETTLE
    assert [e.op for e in tools.edits] == ["open", "add"]
    assert tools.search_contents(fridge, floor=1)["receptacles"][0]["inside"][0]["id"] == r["placed"]


def test_remove_object_and_moves(tools: SceneTools) -> None:
    table = _kitchen(tools, "DiningTable")
    st = tools.ws.floor(1)
    counter_takes = database().receptacles["CounterTop"]
    first = next(c.id for c in st.objects[table].obj.children if st.objects[c.id].props.object_type in counter_takes)
    with pytest.raises(InvalidInputError, match="one of the two"):
        tools.remove_object()
    with pytest.raises(UnknownObjectError):
        tools.remove_object(object_id="staff_kitchen|ghost", floor=1)
    counter = next(i for i in tools.ws.of_type(1, "CounterTop") if i.room == "staff_kitchen").id
    kind = st.objects[first].props.object_type
    moved = tools.place_on_surface(first, counter, floor=1)
    assert moved["placed"] == first and st.objects[first].parent == counter and tools.edits[-1].op == "move"
    removed = tools.remove_object(receptacle_id=table, floor=1)["removed"]
    assert first not in removed and st.objects[table].obj.children == []
    assert tools.remove_object(object_id=first, floor=1)["removed"] == [first]
    assert first not in st.objects and kind
    assert tools.remove_object(receptacle_id=table, floor=1)["removed"] == []


def test_run_dispatches_and_reports_typed_errors(tools: SceneTools) -> None:
    ok, answer = tools.run("ListObjects", {"room": "staff_kitchen", "floor": 1})
    assert ok and answer["count"] > 0
    ok, answer = tools.run("PlaceInContainer", {"asset_id": "Wine_Bottle_1", "container_id": _kitchen(tools, "Fridge"), "floor": 1})
    assert not ok and answer["error"].startswith("ContainerClosedError")
    ok, answer = tools.run("Teleport", {})
    assert not ok and "no tool" in answer["error"]
    ok, answer = tools.run("CheckPath", {"start": "lobby"})
    assert not ok and "bad arguments" in answer["error"]


# -- variants -----------------------------------------------------------------------------------
def test_apply_then_revert_restores_the_base_byte_for_byte(office: Path, tmp_path: Path) -> None:
    root = _copy(office, tmp_path)
    r = edit_building(root, EditSpec.model_validate(PAPER), name="v1")
    assert r.ok
    base = {p.name: p.read_bytes() for p in (root / "scenes").glob("*.json")}
    written = apply_variant(root, "v1")
    assert [p.name for p in written] == ["floor_1.json"]
    assert (root / "scenes" / "floor_1.json").read_bytes() == (r.variant / "scenes" / "floor_1.json").read_bytes()
    with pytest.raises(EditError, match="revert it first"):
        apply_variant(root, "v1")
    name, _ = revert_variant(root)
    assert name == "v1"
    assert {p.name: p.read_bytes() for p in (root / "scenes").glob("*.json")} == base
    with pytest.raises(EditError, match="no variant is applied"):
        revert_variant(root)
    (root / "scenes" / "floor_1.json").write_bytes(base["floor_1.json"] + b" ")
    with pytest.raises(EditError, match="changed since"):
        apply_variant(root, "v1")
    with pytest.raises(InvalidInputError, match="no variant 'nope'"):
        apply_variant(root, "nope")


def test_patch_records_moves_removals_and_changes(tools: SceneTools) -> None:
    from mansion.edit.variants import diff_house

    st = tools.ws.floor(1)
    table = _kitchen(tools, "DiningTable")
    on_table = [c.id for c in st.objects[table].obj.children]
    book = next(c for c in on_table if st.objects[c].props.object_type in database().receptacles["CounterTop"])
    bowl = next(c for c in on_table if c != book)
    counter = next(i for i in tools.ws.of_type(1, "CounterTop") if i.room == "staff_kitchen").id
    tools.place_on_surface(book, counter, floor=1)
    tools.remove_object(object_id=bowl, floor=1)
    tools.place_in_container("Apple_1", _kitchen(tools, "Fridge"), floor=1, open=True)
    base, now = json.loads(tools.ws.base_bytes(1)), json.loads(tools.ws.house_bytes(1))
    p = diff_house(base, now, 1, "floor_1.json", "sha")
    assert [m.id for m in p.moved] == [book] and p.moved[0].parent == counter
    assert [r.id for r in p.removed] == [bowl]
    assert [a.object["assetId"] for a in p.added] == ["Apple_1"] and p.changed[0].set == {"openness": 1.0}
    assert house_text(patch_house(base, p)).encode() == tools.ws.house_bytes(1)


# -- the command line ---------------------------------------------------------------------------
def test_cli_edit_list_apply_revert(office: Path, tmp_path: Path) -> None:
    root = _copy(office, tmp_path)
    spec = tmp_path / "task.json"
    spec.write_text(json.dumps(PAPER))
    result = runner.invoke(app, ["edit", str(root), "--spec", str(spec), "--name", "paper"])
    assert result.exit_code == 0, result.output
    out = result.output
    assert "precondition: the agent starts in lobby on floor 0" in out
    assert "precondition: a WineBottle in a Fridge on floor 1" in out
    assert "✓ OracleAgent: done" in out and "+ added" in out and "+ opened" in out
    assert f"variant: {root / 'variants' / 'paper'}" in out
    result = runner.invoke(app, ["variants", "list", str(root)])
    assert result.exit_code == 0 and "paper: 2 added, 1 changed" in result.output
    result = runner.invoke(app, ["variants", "show", str(root), "paper"])
    assert result.exit_code == 0 and "floor 1 (floor_1.json): 2 added, 0 moved, 0 removed, 1 changed" in result.output
    assert "✓ OracleAgent: done" in result.output
    base = _digests(root)
    assert runner.invoke(app, ["variants", "apply", str(root), "paper"]).exit_code == 0
    assert _digests(root) != base
    assert "(applied)" in runner.invoke(app, ["variants", "list", str(root)]).output
    assert runner.invoke(app, ["validate", str(root / "scenes" / "floor_1.json")]).exit_code == 0
    assert runner.invoke(app, ["variants", "revert", str(root)]).exit_code == 0
    assert _digests(root) == base
    # a task that cannot be made executable: exit 1, naming the precondition
    spec.write_text(json.dumps({**PAPER, "deliver": {"floor": 0, "on": "Bed"}}))
    result = runner.invoke(app, ["edit", str(root), "--spec", str(spec), "--name", "bed"])
    assert result.exit_code == 1
    assert "a Bed on floor 0" in result.output and "floor 0 has no Bed" in result.output
    # bad input: exit 2
    result = runner.invoke(app, ["edit", str(root), "I need a task where ..."])
    assert result.exit_code == 2 and "--planner anthropic" in result.output
    import importlib.util

    if importlib.util.find_spec("ai2thor") is None:
        spec.write_text(json.dumps(PAPER))
        result = runner.invoke(app, ["edit", str(root), "--spec", str(spec), "--settle"])
        assert result.exit_code == 2 and "mansion[ai2thor]" in result.output


# -- the ReAct controller, replayed through the Anthropic SDK -----------------------------------
def test_react_controller_from_recorded_tool_use(office: Path, tmp_path: Path) -> None:
    from llm_replay import Replay

    root = _copy(office, tmp_path)
    replay = Replay()
    r = edit_building(root, text=PAPER["text"], name="paper", planner="anthropic", client=replay.client())
    assert r.ok, r.failed
    assert replay.served == [f"editor_paper.attempt{k}" for k in range(1, 7)]
    first = replay.requests[0]
    assert "scene editing agent" in first["system"] and "Variant: paper" in first["messages"][0]["content"][0]["text"]
    assert {t["name"] for t in first["tools"]} == {
        "CheckPath", "SearchAssets", "ListObjects", "CheckSurface", "SearchContents", "PlaceInContainer",
        "RemoveObject", "PlaceOnSurface", "SubmitTask"}
    # the closed fridge came back to the model as an error result, and it opened the fridge
    results = replay.requests[3]["messages"][-1]["content"]
    closed = next(b for b in results if b.get("is_error"))
    assert "ContainerClosedError" in closed["content"]
    # the model's edits, then the offline check finds the objects where it put them
    assert [e.split(" ")[0] for e in r.edits] == ["added", "opened", "added"]
    assert [t.object_type for t in r.task.targets] == ["Apple", "WineBottle"]
    assert any(line.text.startswith("SubmitTask: accepted") for line in r.log.lines)
    assert run_task(BuildingEnv(root, variant="paper"), r.task, OracleAgent).success


def test_cli_anthropic_without_a_key_says_so(office: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.delenv("ANTHROPIC_API_KEY", raising=False)
    result = runner.invoke(app, ["edit", str(office), PAPER["text"], "--planner", "anthropic"])
    assert result.exit_code == 2 and "ANTHROPIC_API_KEY" in result.output
    assert not (office / "variants" / "i-need-a-task-where-the-agent-starts").exists()


def test_react_controller_that_never_submits_fails_clearly(office: Path, tmp_path: Path) -> None:
    from llm_replay import Replay, message

    from mansion.exceptions import PlannerError

    root = _copy(office, tmp_path)
    replay = Replay(overrides={"editor_quit.attempt1": message("I cannot help with that building.")})
    with pytest.raises(PlannerError, match="stopped without SubmitTask: I cannot help"):
        edit_building(root, text="I need a task where the agent fetches a unicorn", name="quit",
                      planner="anthropic", client=replay.client())
    assert not (root / "variants" / "quit").exists()


def test_fetch_anywhere_goes_where_ai2thor_puts_it_most(office: Path, tmp_path: Path) -> None:
    root = _copy(office, tmp_path)
    assert not any(i.props.object_type == "Potato" for i in Workspace(root).floor(1).objects.values())
    spec = {**PAPER, "fetch": [{"object_type": "Potato", "floor": 1}], "deliver": {"floor": 0, "on": "SideTable"}}
    r = edit_building(root, EditSpec.model_validate(spec), name="potato")
    assert r.ok, r.failed
    target = r.task.targets[0]
    ws = Workspace(root)
    present = {i.props.object_type for i in ws.floor(1).objects.values() if i.parent is None}
    likely = {t: v["Potato"] for t, v in database().receptacles.items() if "Potato" in v and t in present}
    assert target.receptacle_type == max(likely, key=lambda t: likely[t])
    assert run_task(BuildingEnv(root, variant="potato"), r.task, OracleAgent).success


@pytest.mark.slow  # filling four sofas to the brim takes a few hundred placements
def test_a_full_destination_is_cleared_largest_first(office: Path, tmp_path: Path) -> None:
    root = _copy(office, tmp_path)
    ws = Workspace(root)
    filler = SceneTools(ws)
    sofas = [s.id for s in ws.of_type(0, "Sofa")]
    for sofa in sofas:  # books, then apples between them, then pencils in the gaps
        for asset in ("Book_1", "Apple_29", "Pencil_1"):
            with pytest.raises(SurfaceFullError):
                for _ in range(200):
                    filler.place_on_surface(asset, sofa, floor=0)
    ws.building.house(0).to_json(root / "scenes" / "floor_0.json")  # a building with cluttered sofas
    r = edit_building(root, EditSpec.model_validate(PAPER), name="cleared")
    assert r.ok, r.failed
    removed = [e for e in r.edits if e.startswith("removed")]
    in_lobby = sorted(s for s in sofas if ws.floor(0).objects[s].room == "lobby")
    assert removed and r.task.destination.receptacle == in_lobby[0], "the start room's sofa, cleared"
    v = load_variant(root, "cleared")
    floor0 = next(p for p in v.patch if p.floor == 0)
    assert len(floor0.removed) == len(removed) and not floor0.added
    base = json.loads((root / "scenes" / "floor_0.json").read_bytes())
    assert house_text(patch_house(base, floor0)).encode() == (r.variant / "scenes" / "floor_0.json").read_bytes()
    assert run_task(BuildingEnv(root, variant="cleared"), r.task, OracleAgent).success


class SettlingController:
    """Stands in for ``ai2thor.controller.Controller`` (the Unity build cannot be had here): on
    ``reset`` it reports every object of the house as settled ``drop`` metres lower."""

    def __init__(self, drop: float = 0.004, lose: str | None = None):
        self.drop, self.lose = drop, lose
        self.scenes: list[dict[str, Any]] = []

    def reset(self, scene: dict[str, Any]) -> Any:
        self.scenes.append(scene)
        objects = []

        def walk(items: list[dict[str, Any]]) -> None:
            for o in items:
                if o["id"] != self.lose:
                    p = o["position"]
                    centre = {"x": p["x"], "y": p["y"] - self.drop, "z": p["z"]}
                    objects.append({"objectId": o["id"], "position": {**centre, "y": centre["y"] - 0.05},
                                    "axisAlignedBoundingBox": {"center": centre}})
                walk(o.get("children", []))

        walk(scene["objects"])
        return type("Event", (), {"metadata": {"lastActionSuccess": True, "objects": objects}})()


def test_placed_objects_settle_in_the_simulator(office: Path, tmp_path: Path, paper_variant: Any) -> None:
    root = _copy(office, tmp_path)
    ctrl = SettlingController()
    r = edit_building(root, EditSpec.model_validate(PAPER), name="settled", settle_with=ctrl)
    assert r.ok, r.failed
    assert len(ctrl.scenes) == 1 and ctrl.scenes[0]["metadata"]["mansion"]["floor"] == 1
    settled = [line.text for line in r.log.lines if line.text.startswith("settled ")]
    assert len(settled) == 2 and all("moved 0.004 m" in s for s in settled)

    def ys(path: Path) -> dict[str, float]:
        out: dict[str, float] = {}

        def walk(items: list[dict[str, Any]]) -> None:
            for o in items:
                out[o["id"]] = o["position"]["y"]
                walk(o.get("children", []))

        walk(json.loads(path.read_text())["objects"])
        return out

    settled_y = ys(r.variant / "scenes" / "floor_1.json")
    placed_y = ys(paper_variant.variant / "scenes" / "floor_1.json")
    for t in r.task.targets:
        assert settled_y[t.object_id] == pytest.approx(placed_y[t.object_id] - 0.004, abs=1e-4)
    apple = paper_variant.task.targets[0].object_id
    lost = edit_building(_copy(office, tmp_path / "b"), EditSpec.model_validate(PAPER), name="lost",
                         settle_with=SettlingController(lose=apple))
    assert not lost.ok and f"did not spawn {apple}" in (lost.failed or "")


def test_an_object_found_in_a_closed_container_gets_it_opened(office: Path, tmp_path: Path) -> None:
    root = _copy(office, tmp_path)
    ws = Workspace(root)
    tools = SceneTools(ws)
    fridge = _kitchen(tools, "Fridge")
    bottle = tools.place_in_container("Wine_Bottle_1", fridge, floor=1, open=True)["placed"]
    ws.floor(1).objects[fridge].obj.openness = 0.0  # the drink is in the fridge, which is shut
    ws.building.house(1).to_json(root / "scenes" / "floor_1.json")
    spec = {**PAPER, "fetch": [PAPER["fetch"][1]]}
    r = edit_building(root, EditSpec.model_validate(spec), name="shut")
    assert r.ok, r.failed
    assert r.task.targets[0].object_id == bottle
    assert r.edits == [f"opened {fridge} (Fridge)"]
    assert run_task(BuildingEnv(root, variant="shut"), r.task, OracleAgent).success
