"""A PEP 517 build backend for the thin package at the repository's root.

pre-commit installs a ``language: python`` hook with ``pip install .`` at the root of the
hook's repository. Building the root package must not compile ``ekb``: this backend writes
a wheel ``ekb-pre-commit`` with no files, whose one requirement is the wheel ``ekb`` of the
same version (the version of ``[workspace.package]`` in Cargo.toml, its one place). It uses
the standard library only, so pip needs nothing from an index to build it.
"""

import base64
import hashlib
import re
import zipfile
from pathlib import Path

NAME = "ekb-pre-commit"
SUMMARY = "The pre-commit hooks of ekb, with ekb installed from its wheel"
ROOT = Path(__file__).resolve().parent.parent


def version():
    """The version of ``[workspace.package]`` in the root Cargo.toml."""
    manifest = (ROOT / "Cargo.toml").read_text(encoding="utf-8")
    section = re.search(r"^\[workspace\.package\]\n(.*?)(?=^\[|\Z)", manifest, re.M | re.S)
    found = section and re.search(r'^version\s*=\s*"([^"]+)"', section.group(1), re.M)
    if not found:
        raise RuntimeError("Cargo.toml has no `version` in [workspace.package]")
    return found.group(1)


def metadata():
    return (
        "Metadata-Version: 2.1\n"
        f"Name: {NAME}\n"
        f"Version: {version()}\n"
        f"Summary: {SUMMARY}\n"
        "License: MIT\n"
        f"Requires-Dist: ekb=={version()}\n"
    )


def dist_info():
    return f"{NAME.replace('-', '_')}-{version()}.dist-info"


def get_requires_for_build_wheel(config_settings=None):
    return []


def prepare_metadata_for_build_wheel(metadata_directory, config_settings=None):
    folder = Path(metadata_directory) / dist_info()
    folder.mkdir(parents=True, exist_ok=True)
    (folder / "METADATA").write_text(metadata(), encoding="utf-8")
    return folder.name


def build_wheel(wheel_directory, config_settings=None, metadata_directory=None):
    name = f"{NAME.replace('-', '_')}-{version()}-py3-none-any.whl"
    files = {
        f"{dist_info()}/METADATA": metadata(),
        f"{dist_info()}/WHEEL": (
            "Wheel-Version: 1.0\n"
            "Generator: pre_commit_package\n"
            "Root-Is-Purelib: true\n"
            "Tag: py3-none-any\n"
        ),
    }
    record = f"{dist_info()}/RECORD"
    lines = [f"{path},{digest(text.encode())},{len(text.encode())}" for path, text in files.items()]
    files[record] = "\n".join([*lines, f"{record},,"]) + "\n"
    with zipfile.ZipFile(Path(wheel_directory) / name, "w", zipfile.ZIP_DEFLATED) as wheel:
        for path, text in files.items():
            wheel.writestr(path, text)
    return name


def digest(data):
    hashed = base64.urlsafe_b64encode(hashlib.sha256(data).digest()).rstrip(b"=")
    return "sha256=" + hashed.decode()
