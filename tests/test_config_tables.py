"""A config whose [observer] table is not a table: one line naming the file and the key,
exit code 2 (the bad-input corpus's rule), never a TypeError from building the config."""

from __future__ import annotations

from pathlib import Path

import pytest

from observer_node import cli

MODEL = Path(__file__).resolve().parents[1] / "observer_node/examples/bench-loop/model.json"

NOT_TABLES = {
    "a number": "observer = 3",
    "a string": 'observer = "vcan0"',
    "a list": "observer = [1, 2]",
    "a list of pairs": 'observer = [["channel", "vcan0"]]',
    "a boolean": "observer = true",
    "an array of tables": "[[observer]]\nchannel = 'vcan0'",
}


@pytest.mark.parametrize("case", sorted(NOT_TABLES))
def test_observer_that_is_not_a_table_is_one_line(case, tmp_path, capsys):
    cfg = tmp_path / "config.toml"
    cfg.write_text(NOT_TABLES[case] + "\n")
    code = cli.main(["run", "--config", str(cfg), "--model", str(MODEL), "--interface",
                     "virtual", "--channel", "not-a-table", "--record",
                     str(tmp_path / "r.mcap")])
    err = capsys.readouterr().err
    assert code == 2, err
    assert "Traceback" not in err
    (line,) = err.strip().splitlines()
    assert str(cfg) in line and "observer" in line and "table" in line
    assert not (tmp_path / "r.mcap").exists()
