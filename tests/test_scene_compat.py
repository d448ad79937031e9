"""Relation compatibility checker: each contradiction is found, with a reason; sound input passes."""

from __future__ import annotations

from logicenveval.domain.catalog import load_catalog
from logicenveval.scene.compat import check_relations
from logicenveval.scene.spec import ObjectRequest, RelationRequest

CAT = load_catalog()


def _o(i: str, cat: str, placement: str = "floor", room: str = "r") -> ObjectRequest:
    return ObjectRequest(id=i, category=cat, room=room, placement=placement)


def _r(t: str, *args: str) -> RelationRequest:
    return RelationRequest(type=t, args=args)


def _codes(objs: list[ObjectRequest], rels: list[RelationRequest]) -> set[str]:
    return {p.code for p in check_relations(objs, rels, CAT)}


def test_compatible_scene_has_no_problems() -> None:
    objs = [_o("sofa", "sofa"), _o("table", "coffee_table"), _o("book", "book", "on:table"),
            _o("box", "toy_box"), _o("toy", "toy", "inside:box"), _o("art", "painting", "wall")]
    rels = [_r("near", "table", "sofa"), _r("on", "book", "table"), _r("inside", "toy", "box"),
            _r("wall_mounted", "art"), _r("edge", "sofa")]
    assert check_relations(objs, rels, CAT) == []


def test_each_contradiction_is_reported() -> None:
    objs = [_o("a", "coffee_table"), _o("b", "side_table"), _o("sofa", "sofa"), _o("book", "book"),
            _o("bowl", "bowl"), _o("c", "desk"), _o("k", "kitchen_counter", room="other")]
    assert "mutual_on" in _codes(objs, [_r("on", "a", "b"), _r("on", "b", "a")])
    assert "not_a_container" in _codes(objs, [_r("inside", "book", "a")])
    assert "not_a_surface" in _codes(objs, [_r("on", "book", "bowl")])
    assert "too_big_for_surface" in _codes(objs, [_r("on", "sofa", "b")])
    assert "near_and_far" in _codes(objs, [_r("near", "a", "sofa"), _r("far", "sofa", "a")])
    assert "wall_mounted_floor_object" in _codes(objs, [_r("wall_mounted", "sofa")])
    assert "cycle" in _codes(objs, [_r("on", "a", "b"), _r("on", "b", "c"), _r("on", "c", "a")])
    assert "on_and_inside" in _codes(objs, [_r("on", "book", "a"), _r("inside", "book", "bowl")])
    assert "unknown_object" in _codes(objs, [_r("near", "a", "ghost")])
    assert "different_rooms" in _codes(objs, [_r("near", "a", "k")])
    assert "wall_mounted_floor_object" in _codes([_o("s", "sofa", "wall")], [])


def test_reasons_name_objects_and_keep_relation_identity() -> None:
    objs = [_o("sofa", "sofa"), _o("a", "coffee_table")]
    near, far = _r("near", "a", "sofa"), _r("far", "a", "sofa")
    (p,) = check_relations(objs, [near, far], CAT)
    assert "a" in p.reason and "sofa" in p.reason
    assert any(r is near for r in p.relations) and any(r is far for r in p.relations)
