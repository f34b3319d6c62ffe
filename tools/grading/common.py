"""What every part of the grader shares: where the checkout is, the sandbox users, size limits."""
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
NOBODY = 65534
SANDBOX_UID = 61000  # grading tree k runs student code as uid 61000 + k (when the grader is root)
BUILDER_UID = 61500  # and compiles it as uid 61500 + k
MAX_TAPE_BYTES = 64 << 20  # what a judge reads of a runner's tape at most
MAX_FILE_BYTES = 1 << 20  # a larger "exercise file" is not source code


def log(msg):
    print(msg, file=sys.stderr, flush=True)
