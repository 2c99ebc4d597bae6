"""The checks every script of tests/cli keeps.

A failed check is collected with its message rather than raised, so that one run reports every
fault it finds; report() prints them and gives the script's exit status (1 if any failed).
"""

failures = []


def check(ok, message):
    """Records `message` as a failure unless `ok`; returns `ok`, on which later checks may depend."""
    if not ok:
        failures.append(message)
    return ok


def report():
    """Prints each failure and their count; returns the exit status for sys.exit."""
    for f in failures:
        print("FAIL:", f)
    print(f"{len(failures)} failures")
    return 1 if failures else 0
