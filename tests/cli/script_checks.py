"""The checks of the CLI test scripts: each failed check is printed and
counted, and the script's exit status says whether any failed.

  from script_checks import check, finish
  check(value == expected, "what differs")
  finish("what was compared")  # exits 1 after a failed check, 0 otherwise
"""
import sys

failures = []


def check(ok, message):
    if not ok:
        failures.append(message)
        print("FAIL:", message)


def finish(summary=""):
    print(f"{len(failures)} failures{'; ' + summary if summary else ''}")
    sys.exit(1 if failures else 0)
