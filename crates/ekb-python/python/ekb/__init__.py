"""Load and check the environment knowledge base of a tour-guide robot.

``load(path)`` gives the knowledge base as the robot loads it, or raises ``RefusedError``
with every finding of ``ekb check`` when the file has an error; ``check(path)`` gives the
findings. The ``ekb`` command that comes with this package does the rest (``ekb --help``).
"""

from ekb._ekb import (
    Finding,
    KnowledgeBase,
    LoadError,
    Location,
    Point,
    Pose,
    RefusedError,
    UnreadableError,
    __version__,
    check,
    load,
)

__all__ = [
    "Finding",
    "KnowledgeBase",
    "LoadError",
    "Location",
    "Point",
    "Pose",
    "RefusedError",
    "UnreadableError",
    "__version__",
    "check",
    "load",
]
