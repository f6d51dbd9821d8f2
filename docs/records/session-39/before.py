"""The loop's screening module as it was at a commit, read from git (for the records beside
this file, which compare it with today's). Run from the repository's clone."""
import subprocess
import sys
import types


def screening_at(commit: str) -> types.ModuleType:
    source = subprocess.run(["git", "show", f"{commit}:observer_node/loop/screening.py"],
                            capture_output=True, text=True, check=True).stdout
    module = types.ModuleType("observer_node.loop.screening_before")
    module.__package__ = "observer_node.loop"
    sys.modules[module.__name__] = module  # its dataclass looks itself up there
    exec(compile(source, f"{commit}:observer_node/loop/screening.py", "exec"), module.__dict__)
    return module
