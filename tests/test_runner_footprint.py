"""The run folder's size by part, as `run` prints it at the end."""

from __future__ import annotations

from pathlib import Path

from logicenveval.runner.footprint import folder_bytes, size_text


def test_sizes_by_top_level_part_largest_first(tmp_path: Path) -> None:
    (tmp_path / "units" / "cot").mkdir(parents=True)
    (tmp_path / "units" / "cot" / "a.json").write_bytes(b"x" * 3000)
    (tmp_path / "units" / "b.json").write_bytes(b"x" * 1000)
    (tmp_path / "results.json").write_bytes(b"x" * 500)
    (tmp_path / "envs").mkdir()
    (tmp_path / "envs" / "link.json").symlink_to(tmp_path / "results.json")  # not counted twice
    assert folder_bytes(tmp_path) == {"units": 4000, "results.json": 500, "envs": 0}
    assert size_text(folder_bytes(tmp_path), parts=1) == "0.0 MB (units 0.0 MB, other 0.0 MB)"
    (tmp_path / "units" / "big.json").write_bytes(b"x" * 2_500_000)
    assert size_text(folder_bytes(tmp_path)).startswith("2.5 MB (units 2.5 MB, results.json 0.0 MB")


def test_a_missing_folder_is_empty(tmp_path: Path) -> None:
    assert folder_bytes(tmp_path / "nope") == {}
    assert size_text({}) == "0.0 MB"
