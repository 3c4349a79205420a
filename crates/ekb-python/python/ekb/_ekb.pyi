"""Type stubs of ``ekb._ekb``, the native part of ``ekb`` (written in Rust)."""

import os
from typing import Any, Literal, Optional, Union

__version__: str

_Path = Union[str, "os.PathLike[str]"]
_Reader = Literal["d5.4.2", "2025-06", "2026-02", "2026-03", "2026-04"]

class Finding:
    """One finding of ``ekb check``: 1-based lines and columns (columns count
    characters), the end exclusive. ``str(finding)`` is its line in
    ``ekb check --format concise``: ``file:line:column: severity[rule] message``.
    It pickles."""

    @property
    def file(self) -> str: ...
    @property
    def rule(self) -> str: ...
    @property
    def severity(self) -> Literal["error", "warning", "info"]: ...
    @property
    def message(self) -> str: ...
    @property
    def line(self) -> int: ...
    @property
    def column(self) -> int: ...
    @property
    def end_line(self) -> int: ...
    @property
    def end_column(self) -> int: ...
    @property
    def location_id(self) -> Optional[int]: ...
    @property
    def help(self) -> Optional[str]: ...

class Pose:
    """Where the robot stands, in metres, and the way it faces, in degrees."""

    @property
    def x(self) -> float: ...
    @property
    def y(self) -> float: ...
    @property
    def theta(self) -> float: ...

class Point:
    """The point the robot gestures at, in metres (``0 0 0``: no gesture)."""

    @property
    def x(self) -> float: ...
    @property
    def y(self) -> float: ...
    @property
    def z(self) -> float: ...

class Location:
    """One location, as ``ekb export`` shows it: a field absent from the file is None."""

    @property
    def id(self) -> int: ...
    @property
    def description(self) -> Optional[str]: ...
    @property
    def pose(self) -> Optional[Pose]: ...
    @property
    def gesture_target(self) -> Optional[Point]: ...
    @property
    def gesture_arm(self) -> Optional[Literal["left", "right"]]: ...
    @property
    def cultural_knowledge(self) -> list[str]: ...
    def message(self, phase: str, language: str) -> Optional[str]:
        """What the robot says before (``phase="pre"``) or after (``"post"``) the
        gesture, in ``language`` (``"english"``, ``"isizulu"``, ``"kinyarwanda"``, or
        ``"en"``, ``"zu"``, ``"rw"``); None when the file has no such message.
        ``ValueError`` for an unknown phase or language."""

class KnowledgeBase:
    """A knowledge base that ``ekb check`` finds no error in, as the robot loads it.
    ``kb[id]``, ``id in kb`` and ``len(kb)`` work on location ids, as a ``dict`` keyed
    by id: ``kb[key]`` is ``KeyError`` and ``key in kb`` is False for any key that is not
    the id of a location (``-1``, ``2**40``, ``"x"``)."""

    @property
    def file(self) -> str: ...
    @property
    def reader(self) -> _Reader:
        """The version of the robot's reader the file was checked against."""
    @property
    def dialect(self) -> Optional[Literal["seed", "current"]]: ...
    @property
    def locations(self) -> list[Location]:
        """Every location, in ascending id order."""
    @property
    def tour(self) -> list[int]:
        """The ids of the tour's stops, in the order visited."""
    @property
    def findings(self) -> list[Finding]:
        """The warnings and notes of the check (a loaded file has no error)."""
    def location(self, id: object) -> Location:
        """The location with this id; ``KeyError`` for any key that is not the id of one."""
    def export(self) -> dict[str, Any]:
        """The whole knowledge base as a dict in the shape of ``ekb export``."""
    def __getitem__(self, id: object) -> Location: ...
    def __contains__(self, id: object) -> bool: ...
    def __len__(self) -> int: ...

class LoadError(Exception):
    """A knowledge base was not loaded. ``findings`` tells why (empty when the file
    could not be read). Its texts (``str(error)``, ``file``, the findings') quote file
    names and values escaped and cut as ``ekb check`` shows them. It pickles with its
    findings (``multiprocessing`` hands it from one process to another)."""

    findings: list[Finding]
    file: Optional[str]

class RefusedError(LoadError):
    """The file has an error: the robot would load something other than it says.
    ``findings`` has every finding of the check, errors and warnings."""

class UnreadableError(LoadError):
    """The file, or the project settings named by ``settings``, could not be read."""

def load(
    path: _Path, *, reader: Optional[_Reader] = None, settings: Optional[_Path] = None
) -> KnowledgeBase:
    """Load the knowledge base at ``path`` as the robot should: ``RefusedError`` with
    every finding if ``ekb check`` finds an error in it, ``UnreadableError`` if it
    cannot be read. ``reader``: the robot's reader to check against (default: the one
    ``settings`` names, else the one of the file's dialect). ``settings``: the project
    settings (``ekb.toml``) to check with, as ``ekb check --settings``; none by default
    (as ``ekb check --isolated``): an ``ekb.toml`` above the file is not read."""

def check(
    path: _Path, *, reader: Optional[_Reader] = None, settings: Optional[_Path] = None
) -> list[Finding]:
    """Check the knowledge base at ``path`` as ``ekb check --isolated`` does (or with
    ``settings``, as ``ekb check --settings``): its findings, errors first, a consequence
    after its cause (empty for a clean file). ``UnreadableError`` if it cannot be read."""
