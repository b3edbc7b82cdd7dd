"""What the end-to-end test scripts share: their arguments, failing with a message, and a fresh
scratch folder per case. Each script is run as: python3 SCRIPT FIRN REPO_ROOT SCRATCH_DIR TEST."""
import os
import shutil
import sys

FIRN, ROOT, SCRATCH, TEST = sys.argv[1:5]


def check(cond, message):
    if not cond:
        sys.exit("FAIL: " + message)


def fresh(name):
    path = os.path.join(SCRATCH, name)
    shutil.rmtree(path, ignore_errors=True)
    return path
