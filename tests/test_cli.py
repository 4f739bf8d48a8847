"""The CLI front door: failures are one line on stderr with the documented exit status, never a traceback."""

import types

import pytest

from fem import ConvergenceError
from wear.app import cli


def _fake(monkeypatch, exc):
    module = types.SimpleNamespace(main=lambda args: (_ for _ in ()).throw(exc))
    parser = cli.build_parser()
    real_parse = parser.parse_known_args

    def parse(argv):
        args, unknown = real_parse(argv)
        args._module = module
        return args, unknown

    parser.parse_known_args = parse
    monkeypatch.setattr(cli, "build_parser", lambda: parser)


@pytest.mark.parametrize(
    "exc, status, text",
    [
        (ValueError("speed=-1 is out of range: impact speed must be in (0, 1000] m/s"), 2, "speed=-1"),
        (ConvergenceError("Newton did not converge at overlap=1e-06 m"), 1, "overlap=1e-06 m"),
    ],
)
def test_errors_are_one_line(monkeypatch, capsys, exc, status, text):
    _fake(monkeypatch, exc)
    assert cli.main(["impact"]) == status
    err = capsys.readouterr().err
    assert len(err.strip().splitlines()) == 1 and text in err and "Traceback" not in err


def test_no_command_prints_help_and_exits_2(capsys):
    assert cli.main([]) == 2
    assert "COMMAND" in capsys.readouterr().out
