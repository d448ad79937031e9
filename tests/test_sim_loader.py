"""BT.CPP v4 loader: both leaf spellings, SubTree/include, errors with line numbers, round trip."""

from __future__ import annotations

from pathlib import Path

import pytest
from sim_support import POLICIES, living_room_task

from logicenveval.errors import PolicyFormatError
from logicenveval.sim.loader import (
    BadPortError,
    UnknownNodeError,
    load_policy,
    policy_from_xml,
    policy_to_xml,
)

ROLES = ["toy", "box", "sofa"]


def doc(body: str, extra: str = "") -> str:
    return ('<root BTCPP_format="4" main_tree_to_execute="Main">\n'
            f'  <BehaviorTree ID="Main">\n{body}\n  </BehaviorTree>\n{extra}</root>\n')


def err(text: str, cls: type[PolicyFormatError] = PolicyFormatError) -> PolicyFormatError:
    with pytest.raises(cls) as info:
        policy_from_xml(text, "p.xml", roles=ROLES)
    return info.value


def test_both_leaf_spellings_give_the_same_policy() -> None:
    a = policy_from_xml(doc('<Sequence><Pick obj="toy"/><On obj="toy" target="floor"/></Sequence>'))
    b = policy_from_xml(doc('<Sequence><Action ID="Pick" obj="toy"/>'
                            '<Condition ID="On" obj="toy" target="floor"/></Sequence>'))
    assert a == b


def test_unknown_node_names_line_and_valid_names() -> None:
    e = err(doc('    <Sequence>\n      <Pick obj="toy"/>\n      <Jump obj="toy"/>\n    </Sequence>'),
            UnknownNodeError)
    assert e.line == 5 and "Jump" in str(e) and "PutIn" in str(e) and "p.xml:5" in str(e)


def test_missing_and_extra_port() -> None:
    e = err(doc('    <Place obj="toy"/>'), BadPortError)
    assert e.line == 3 and "missing port 'target'" in str(e)
    e = err(doc('    <Pick obj="toy" speed="2"/>'), BadPortError)
    assert "no port 'speed'" in str(e) and "obj" in str(e)


def test_unknown_role() -> None:
    e = err(doc('    <Sequence>\n      <Walk target="teddy"/>\n    </Sequence>'), BadPortError)
    assert e.line == 4 and "teddy" in str(e) and "box, sofa, toy" in str(e)
    # floor and room names are fine where they make sense
    policy_from_xml(doc('<Sequence><Walk target="Kitchen"/><Place obj="toy" target="floor"/>'
                        '</Sequence>'), roles=ROLES)


@pytest.mark.parametrize("node", ["Timeout msec=\"10\"", "Delay delay_msec=\"5\"",
                                  "Script code=\"x:=1\"", "SetBlackboard value=\"1\" output_key=\"k\""])
def test_rejected_nodes(node: str) -> None:
    e = err(doc(f'    <Sequence>\n      <{node}/>\n    </Sequence>'))
    assert e.line == 4 and node.split()[0] in str(e) and "not supported" in str(e)


def test_blackboard_value_rejected() -> None:
    e = err(doc('    <Sequence>\n\n      <Pick obj="{target}"/>\n    </Sequence>'))
    assert e.line == 5 and "blackboard" in str(e)


def test_subtree_remapping_rejected() -> None:
    e = err(doc('    <SubTree ID="Sub" obj="toy"/>',
                '  <BehaviorTree ID="Sub"><Pick obj="toy"/></BehaviorTree>\n'))
    assert e.line == 3 and "remapping" in str(e)


def test_subtree_unknown_and_recursive() -> None:
    assert "names no BehaviorTree" in str(err(doc('    <SubTree ID="Nope"/>')))
    text = doc('    <SubTree ID="Main"/>')
    assert "recursive" in str(err(text))


def test_xml_syntax_and_format() -> None:
    assert err('<root BTCPP_format="4">\n<BehaviorTree ID="M"><Pick obj="toy">\n</root>').line == 3
    assert "BTCPP_format" in str(err('<root BTCPP_format="3"><BehaviorTree ID="M"/></root>'))


def test_entities_are_forbidden() -> None:
    text = '<?xml version="1.0"?><!DOCTYPE r [<!ENTITY a "x">]><root BTCPP_format="4"/>'
    assert "forbidden" in str(err(text)) or "DTD" in str(err(text))


def test_tree_nodes_model_checked() -> None:
    good = ('  <TreeNodesModel>\n    <Action ID="Pick"><input_port name="obj"/></Action>\n'
            '  </TreeNodesModel>\n')
    policy_from_xml(doc('    <Pick obj="toy"/>', good))
    bad = ('  <TreeNodesModel>\n    <Action ID="Pick"><input_port name="thing"/></Action>\n'
           '  </TreeNodesModel>\n')
    e = err(doc('    <Pick obj="toy"/>', bad))
    assert e.line == 6 and "Pick" in str(e) and "thing" in str(e)
    wrong_kind = ('  <TreeNodesModel>\n    <Condition ID="Pick"><input_port name="obj"/>'
                  '</Condition>\n  </TreeNodesModel>\n')
    assert "<Action>" in str(err(doc('    <Pick obj="toy"/>', wrong_kind)))


def test_tree_nodes_model_extra_nodes_ignored_unless_used() -> None:
    palette = ('  <TreeNodesModel>\n    <Action ID="Fly"><input_port name="obj"/></Action>\n'
               '    <Condition ID="IsBatteryOk"/>\n  </TreeNodesModel>\n')
    policy_from_xml(doc('    <Pick obj="toy"/>', palette), roles=ROLES)
    e = err(doc('    <Fly obj="toy"/>', palette), UnknownNodeError)
    assert e.line == 3 and "Fly" in str(e)


def test_metadata_attributes_ignored() -> None:
    a = policy_from_xml(doc('<Sequence _uid="3" _fullpath="Main/Sequence"><Pick obj="toy" '
                            '_description="grab it"/><SubTree ID="T" _description="x"/></Sequence>',
                            '<BehaviorTree ID="T"><AlwaysSuccess _uid="9"/></BehaviorTree>'))
    b = policy_from_xml(doc('<Sequence><Pick obj="toy"/><SubTree ID="T"/></Sequence>',
                            '<BehaviorTree ID="T"><AlwaysSuccess/></BehaviorTree>'))
    assert a == b
    assert "_skipIf" in str(err(doc('<Pick obj="toy" _skipIf="x"/>')))


def test_id_less_tree_and_missing_format_as_bt_cpp() -> None:
    p = policy_from_xml('<root><BehaviorTree><Pick obj="toy"/></BehaviorTree></root>')
    assert p.main == "BehaviorTree_0" and list(p.trees) == ["BehaviorTree_0"]
    assert len(p.warnings) == 1 and "BTCPP_format" in p.warnings[0]
    assert policy_from_xml(doc('<Pick obj="toy"/>')).warnings == ()
    e = err('<root BTCPP_format="4"><BehaviorTree><Pick obj="toy"/></BehaviorTree>'
            '<BehaviorTree ID="B"><Pick obj="toy"/></BehaviorTree></root>')
    assert "needs an ID" in str(e)
    assert "BTCPP_format='3'" in str(err('<root BTCPP_format="3"><BehaviorTree ID="A">'
                                         '<Pick obj="toy"/></BehaviorTree></root>'))


def test_main_tree_rules_as_bt_cpp(tmp_path: Path) -> None:
    (tmp_path / "lib.xml").write_text('<root BTCPP_format="4"><BehaviorTree ID="Lib">'
                                      '<Pick obj="toy"/></BehaviorTree></root>')
    main = tmp_path / "main.xml"
    main.write_text('<root BTCPP_format="4"><include path="lib.xml"/><BehaviorTree ID="Top">'
                    '<SubTree ID="Lib"/></BehaviorTree></root>')
    assert load_policy(main).main == "Top"  # the file's only tree, includes aside
    main.write_text('<root BTCPP_format="4"><include path="lib.xml"/></root>')
    assert load_policy(main).main == "Lib"  # the only tree loaded
    two = ('<root BTCPP_format="4"><BehaviorTree ID="A"><Pick obj="toy"/></BehaviorTree>'
           '<BehaviorTree ID="B"><Pick obj="toy"/></BehaviorTree></root>')
    assert "main_tree_to_execute" in str(err(two))


def test_async_controls_load() -> None:
    p = policy_from_xml(doc('<AsyncSequence><Pick obj="toy"/><AsyncFallback><Pick obj="toy"/>'
                            '</AsyncFallback></AsyncSequence>'))
    assert policy_to_xml(p).count("Async") == 4


def test_control_node_parameters() -> None:
    assert "num_attempts" in str(err(doc('<RetryUntilSuccessful><Pick obj="toy"/>'
                                         '</RetryUntilSuccessful>')))
    assert "not an integer" in str(err(doc('<Repeat num_cycles="x"><Pick obj="toy"/></Repeat>')))
    assert "exactly one child" in str(err(doc('<Inverter/>')))
    assert "2 or 3" in str(err(doc('<IfThenElse><Pick obj="toy"/></IfThenElse>')))
    assert "at least 2" in str(err(doc('<TryCatch><Pick obj="toy"/></TryCatch>')))
    assert "not a boolean" in str(err(doc('<TryCatch catch_on_halt="maybe"><Pick obj="toy"/>'
                                          '<Pick obj="toy"/></TryCatch>')))
    assert "more than its 1 children" in str(err(doc('<Parallel success_count="3"><Pick obj="toy"/>'
                                                    '</Parallel>')))
    assert "failure_count=2" in str(err(doc('<Parallel failure_count="2"><Pick obj="toy"/>'
                                            '</Parallel>')))


def test_include_relative_to_file(tmp_path: Path) -> None:
    (tmp_path / "sub").mkdir()
    (tmp_path / "sub" / "lib.xml").write_text(
        '<root BTCPP_format="4"><BehaviorTree ID="Grab"><Pick obj="toy"/></BehaviorTree></root>')
    main = tmp_path / "main.xml"
    main.write_text(doc('<SubTree ID="Grab"/>', '  <include path="sub/lib.xml"/>\n'))
    p = load_policy(main, roles=ROLES)
    assert set(p.trees) == {"Main", "Grab"}
    (tmp_path / "bad.xml").write_text(doc('<SubTree ID="Grab"/>', '  <include path="no.xml"/>\n'))
    with pytest.raises(PolicyFormatError, match="not found"):
        load_policy(tmp_path / "bad.xml")


@pytest.mark.parametrize("kind", ["correct", "counterfactual", "unreachable", "lackbranch"])
def test_round_trip(kind: str) -> None:
    task = living_room_task()
    p = load_policy(POLICIES / f"{kind}.xml", roles=task.roles, rooms=task.rooms)
    text = policy_to_xml(p)
    again = policy_from_xml(text, "export.xml", roles=task.roles)
    assert again == p
    assert policy_to_xml(again) == text


def test_round_trip_keeps_names_and_params() -> None:
    p = policy_from_xml(doc('<Parallel name="both" success_count="1" failure_count="2">'
                            '<Pick obj="toy"/><Repeat num_cycles="2"><AlwaysSuccess/></Repeat>'
                            '</Parallel>'))
    assert policy_from_xml(policy_to_xml(p)) == p
    assert 'name="both"' in policy_to_xml(p)


def test_xml_parses_into_py_trees_and_exports_back() -> None:
    import py_trees

    from logicenveval.sim import nodes
    from logicenveval.sim.pytrees_io import load_tree, tree_from_xml, tree_to_xml, unicode_tree

    task = living_room_task()
    for kind in ("correct", "counterfactual", "unreachable", "lackbranch"):
        p = load_policy(POLICIES / f"{kind}.xml", roles=task.roles, rooms=task.rooms)
        root = load_tree(POLICIES / f"{kind}.xml", roles=task.roles, rooms=task.rooms)
        assert all(isinstance(n, py_trees.behaviour.Behaviour) for n in root.iterate())
        text = tree_to_xml(root)
        assert policy_from_xml(text, roles=task.roles, rooms=task.rooms) == p
        assert tree_to_xml(tree_from_xml(text, roles=task.roles, rooms=task.rooms)) == text
    root = load_tree(POLICIES / "correct.xml", roles=task.roles)
    kinds = {type(n) for n in root.iterate()}
    assert {nodes.SubTree, nodes.ActionNode, nodes.ConditionNode} <= kinds
    assert all(isinstance(n, py_trees.composites.Composite) for n in root.iterate()
               if isinstance(n, nodes.Control))
    text = unicode_tree(root)
    assert "PutIn(obj=toy, target=white_box)" in text and "SubTree(TidyBook)" in text


def test_round_trip_of_every_control_node_through_py_trees() -> None:
    from logicenveval.sim.pytrees_io import tree_from_xml, tree_to_xml

    body = ('<Sequence name="all"><SequenceWithMemory><ReactiveSequence><AlwaysSuccess/></ReactiveSequence>'
            '</SequenceWithMemory><Fallback><ReactiveFallback><AlwaysFailure/></ReactiveFallback></Fallback>'
            '<IfThenElse><Holding obj="toy"/><Pick obj="toy"/><AlwaysSuccess/></IfThenElse>'
            '<WhileDoElse><Holding obj="toy"/><AlwaysSuccess/></WhileDoElse>'
            '<Parallel success_count="1" failure_count="2"><AlwaysSuccess/><AlwaysFailure/></Parallel>'
            '<Inverter><ForceSuccess><ForceFailure><AlwaysSuccess/></ForceFailure></ForceSuccess></Inverter>'
            '<RetryUntilSuccessful num_attempts="3"><Repeat num_cycles="2"><KeepRunningUntilFailure>'
            '<AlwaysFailure/></KeepRunningUntilFailure></Repeat></RetryUntilSuccessful>'
            '<AsyncSequence><AsyncFallback><AlwaysFailure/></AsyncFallback></AsyncSequence>'
            '<TryCatch catch_on_halt="1"><AlwaysSuccess/><AlwaysFailure/></TryCatch>'
            '<SubTree ID="Sub"/></Sequence>')
    text = doc(body, '  <BehaviorTree ID="Sub">\n<Walk target="box"/>\n  </BehaviorTree>\n')
    p = policy_from_xml(text, roles=ROLES)
    again = tree_to_xml(tree_from_xml(text, roles=ROLES))
    assert policy_from_xml(again, roles=ROLES) == p
    assert 'catch_on_halt="true"' in again


def test_every_shipped_policy_carries_the_current_groot2_model() -> None:
    from logicenveval.benchmark import DEFAULT_TASKS_DIR
    from logicenveval.sim.groot import model_problem

    files = sorted(DEFAULT_TASKS_DIR.glob("*/policies/*.xml"))
    assert len(files) == 100
    assert [f for f in files if model_problem(f.read_text(encoding="utf-8"))] == []


def test_export_carries_the_model_and_round_trips() -> None:
    from defusedxml.ElementTree import fromstring

    from logicenveval.domain.actions import ACTIONS, CONDITIONS
    from logicenveval.sim.groot import model_problem

    policy = load_policy(POLICIES / "correct.xml")
    text = policy_to_xml(policy)
    assert model_problem(text) is None
    model = fromstring(text).find("TreeNodesModel")
    assert {(d.tag, d.get("ID")) for d in model} == {
        *(("Action", a) for a in ACTIONS), *(("Condition", c) for c in CONDITIONS)}
    place = model.find("Action[@ID='Place']")
    assert [(p.get("name"), p.get("type")) for p in place] [:2] == [
        ("obj", "std::string"), ("target", "std::string")]
    again = policy_from_xml(text)
    assert again == policy and policy_to_xml(again) == text


FORMS = Path(__file__).parent / "fixtures" / "btcpp_forms"


def test_documents_in_bt_cpp_and_groot2_forms_load() -> None:
    # our own XML in the forms BT.CPP's examples and Groot2 project files use (both files load and
    # tick in BehaviorTree.CPP 4.10 with the library nodes registered; see docs/simulator.md)
    p = load_policy(FORMS / "groot2_project.xml", roles=ROLES)
    assert p.main == "Main" and set(p.trees) == {"Main", "TidyToy"} and p.warnings == ()
    assert p.trees["TidyToy"].kind == "TryCatch"
    assert p.trees["Main"].children[0].params == (("ID", "TidyToy"),)  # _description ignored
    t = load_policy(FORMS / "tutorial_form.xml", roles=ROLES)
    assert t.main == "BehaviorTree_0" and "BTCPP_format" in t.warnings[0]
    again = policy_from_xml(policy_to_xml(t), roles=ROLES)
    assert again == t and again.warnings == ()


# ----- issue 27, item 22: what the loader refuses and how --------------------------------

def test_name_attribute_in_braces_is_a_name_not_a_blackboard_port() -> None:
    p = policy_from_xml(doc('    <Sequence name="{step}"><Pick name="{x}" obj="toy"/></Sequence>'),
                        roles=ROLES)
    root = p.trees["Main"]
    assert root.name == "{step}" and root.children[0].name == "{x}"
    assert root.children[0].params == (("obj", "toy"),)
    assert "blackboard" in str(err(doc('    <Pick name="{x}" obj="{toy}"/>')))


@pytest.mark.parametrize(("xml", "says", "fix"), [
    ('<Action ID="Sequence"><Pick obj="toy"/></Action>', "Sequence is a control node, not an action",
     '<Control ID="Sequence">'),
    ('<Control ID="Walk" target="toy"/>', "Walk is an action node, not a control", '<Action ID="Walk"'),
    ('<Decorator ID="Sequence"><Pick obj="toy"/></Decorator>', "control node, not a decorator",
     "<Sequence>"),
    ('<Control ID="Inverter"><Pick obj="toy"/></Control>', "decorator node, not a control",
     '<Decorator ID="Inverter">'),
    ('<Condition ID="Pick" obj="toy"/>', "Pick is an action node, not a condition", '<Action ID="Pick"'),
    ('<Action ID="Holding" obj="toy"/>', "a condition node, not an action", '<Condition ID="Holding"'),
    ('<Condition ID="AlwaysSuccess"/>', "an action node, not a condition", '<Action ID="AlwaysSuccess"'),
    ('<Action ID="SubTree"/>', "not how a SubTree is written", '<SubTree ID='),
])
def test_wrapper_tag_must_match_the_node_type(xml: str, says: str, fix: str) -> None:
    e = err(doc(f"    <Sequence>\n      {xml}\n    </Sequence>"))
    assert e.line == 4 and says in str(e) and e.hint is not None and fix in e.hint


def test_matching_wrappers_load() -> None:
    a = policy_from_xml(doc('<Control ID="Sequence"><Decorator ID="Inverter"><Condition ID="Holding" '
                            'obj="toy"/></Decorator><Action ID="AlwaysSuccess"/></Control>'))
    b = policy_from_xml(doc('<Sequence><Inverter><Holding obj="toy"/></Inverter><AlwaysSuccess/>'
                            '</Sequence>'))
    assert a == b


@pytest.mark.parametrize(("value", "why"), [
    ("1_0", "leading '1'"), ("3 ", "leading '3'"), ("2x", "leading '2'"), (" 3", "ASCII digits"),
    ("+3", "ASCII digits"), ("\u0663", "ASCII digits"), ("３", "ASCII digits"), ("", "ASCII digits"),
    ("0x3", "leading '0'"), ("3.0", "leading '3'"), ("2147483648", "32-bit"), ("-2147483649", "32-bit"),
])
def test_integers_are_ascii_digits_as_behaviortree_cpp_reads_them(value: str, why: str) -> None:
    e = err(doc(f'    <Repeat num_cycles="{value}"><Pick obj="toy"/></Repeat>'))
    assert e.line == 3 and "num_cycles" in str(e) and why in str(e)


@pytest.mark.parametrize(("value", "want"), [("3", "3"), ("-1", "-1"), ("007", "7"),
                                              ("2147483647", "2147483647")])
def test_plain_integers_load(value: str, want: str) -> None:
    p = policy_from_xml(doc(f'<Repeat num_cycles="{value}"><Pick obj="toy"/></Repeat>'))
    assert p.trees["Main"].param("num_cycles") == want


@pytest.mark.parametrize(("value", "want"), [("true", "true"), ("True", "true"), ("TRUE", "true"),
                                              ("1", "true"), ("false", "false"), ("0", "false")])
def test_booleans_as_behaviortree_cpp_spells_them(value: str, want: str) -> None:
    p = policy_from_xml(doc(f'<TryCatch catch_on_halt="{value}"><Pick obj="toy"/>'
                            '<Pick obj="box"/></TryCatch>'))
    assert p.trees["Main"].param("catch_on_halt") == want


@pytest.mark.parametrize("value", ["tRuE", "yes", " true", "2"])
def test_other_boolean_spellings_are_refused(value: str) -> None:
    e = err(doc(f'    <TryCatch catch_on_halt="{value}"><Pick obj="toy"/><Pick obj="box"/></TryCatch>'))
    assert e.line == 3 and "not a boolean" in str(e)


@pytest.mark.parametrize(("body", "says"), [
    ('<Fly obj="toy"/>', "unknown node <Fly>"),
    ('<Pick obj="toy" speed="2"/>', "no port 'speed'"),
    ('<Walk target="teddy"/>', "'teddy' is not a role of the task"),
    ('<Action ID="Sequence"><Pick obj="toy"/></Action>', "not an action node"),
    ('<Repeat num_cycles="1_0"><Pick obj="toy"/></Repeat>', "not an integer"),
])
def test_simulate_cli_exits_2_on_a_policy_it_cannot_load(
        tmp_path: Path, capsys: pytest.CaptureFixture[str], body: str, says: str) -> None:
    """One rule (docs/security.md): a policy that cannot be loaded is bad input, exit 2 with
    file:line and a fix, whatever the reason (unknown node and bad port included)."""
    from logicenveval.cli import main

    policy = tmp_path / "p.xml"
    policy.write_text(f'<root BTCPP_format="4">\n<BehaviorTree ID="M">\n{body}\n'
                      "</BehaviorTree></root>")
    env = Path(__file__).parent / "fixtures" / "envs" / "one_room.json"
    code = main(["simulate", "--task", "clean_living_room", "--policy", str(policy), "--env",
                 str(env)])
    out, errors = capsys.readouterr()
    assert code == 2 and out == "" and "Traceback" not in errors
    assert f"{policy}:3" in errors and says in errors and "(fix: " in errors
