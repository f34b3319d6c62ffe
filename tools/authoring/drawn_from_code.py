"""The command line every picture drawn from the code shares (floors.py, judge_path.py):

  TOOL [ROOT]               the check
  TOOL --self-test [ROOT]   prove the check can fail
  TOOL --svg F [ROOT]       draw the picture into F
  TOOL --check-svg F [ROOT] exit 1 when F is not what --svg would draw now
"""
import pathlib
import sys


def main(argv, name, usage, check, self_test, svg):
    """Runs a tool's check, self-test or picture by `argv`; `name` prefixes what it prints, `usage` is
    printed on a wrong command line. Returns the exit code."""
    args, tool = argv[1:], pathlib.Path(argv[0])
    default = pathlib.Path(__file__).resolve().parents[2]
    if args[:1] == ["--self-test"]:
        return self_test(pathlib.Path(args[1]) if len(args) > 1 else default)
    if args[:1] in (["--svg"], ["--check-svg"]):
        if len(args) < 2:
            print(usage, file=sys.stderr)
            return 2
        root = pathlib.Path(args[2]) if len(args) > 2 else default
        drawn, target = svg(root), pathlib.Path(args[1])
        if args[0] == "--svg":
            target.parent.mkdir(parents=True, exist_ok=True)
            target.write_text(drawn)
            print(f"{name}: wrote {target}")
            return 0
        if not target.exists() or target.read_text() != drawn:
            print(f"{name}: {target} is not what the code draws now; run tools/authoring/{tool.name} --svg {target}")
            return 1
        print(f"{name}: {target} is up to date")
        return 0
    if args and args[0].startswith("-"):
        print(usage, file=sys.stderr)
        return 2
    return check(pathlib.Path(args[0]) if args else default)
