"""mechd_build.py — the build backend (PEP 517) of the mechd Python client, with the
standard library only (zipfile, hashlib, base64): no setuptools, no wheel module, so
`pip install ./clients/python` works on any Python >= 3.8 without a network, and
`make dist` writes the same pure wheel into dist/.

The wheel holds the package mechd: mechd/__init__.py (the single module mechd.py, so
copying mechd.py next to a script keeps working), mechd/__main__.py
(`python3 -m mechd`), mechd/py.typed (PEP 561: mypy and pyright read the inline type
hints), and the dist-info: METADATA (name, version from mechd.py's __version__,
summary, Requires-Python, the README), WHEEL (py3-none-any, Root-Is-Purelib),
entry_points.txt (the mechd-client command) and RECORD (sha256 of every file,
urlsafe base64 without padding, as the wheel spec says).

    python3 clients/python/mechd_build.py DIR     # writes DIR/mechd_client-<v>-py3-none-any.whl

Files are written in a fixed order with a fixed timestamp, so the same sources give
the same bytes.
"""
import base64
import hashlib
import io
import os
import re
import sys
import tarfile
import zipfile

HERE = os.path.dirname(os.path.abspath(__file__))
NAME = "mechd-client"
DIST = "mechd_client"
SUMMARY = "Client for mechd, the mechanics computation server (JSON over HTTP)"
REQUIRES_PYTHON = ">=3.8"
EPOCH = (2020, 1, 1, 0, 0, 0)  # zip timestamps: reproducible wheels

MAIN = '''"""python3 -m mechd: the mechd-client command."""
import sys

from mechd import main

sys.exit(main())
'''


def version():
    """__version__ of mechd.py (the one place the client's version is written)."""
    with open(os.path.join(HERE, "mechd.py"), encoding="utf-8") as f:
        m = re.search(r'^__version__ = "([^"]+)"', f.read(), re.M)
    if not m:
        raise RuntimeError("mechd.py has no __version__")
    return m.group(1)


def _read(name):
    with open(os.path.join(HERE, name), "rb") as f:
        return f.read()


def _metadata(v):
    readme = _read("README.md").decode("utf-8")
    return ("Metadata-Version: 2.1\nName: %s\nVersion: %s\nSummary: %s\n"
            "Requires-Python: %s\nClassifier: Programming Language :: Python :: 3\n"
            "Classifier: Topic :: Scientific/Engineering :: Physics\n"
            "Classifier: Typing :: Typed\n"
            "Description-Content-Type: text/markdown\n\n%s"
            % (NAME, v, SUMMARY, REQUIRES_PYTHON, readme)).encode("utf-8")


def _files(v):
    """(archive name, bytes) of the wheel, RECORD last."""
    info = "%s-%s.dist-info" % (DIST, v)
    files = [
        ("mechd/__init__.py", _read("mechd.py")),
        ("mechd/__main__.py", MAIN.encode()),
        ("mechd/py.typed", b""),
        (info + "/METADATA", _metadata(v)),
        (info + "/WHEEL", b"Wheel-Version: 1.0\nGenerator: mechd_build\n"
                          b"Root-Is-Purelib: true\nTag: py3-none-any\n"),
        (info + "/entry_points.txt", b"[console_scripts]\nmechd-client = mechd:main\n"),
    ]
    record = []
    for name, data in files:
        digest = base64.urlsafe_b64encode(hashlib.sha256(data).digest()).rstrip(b"=")
        record.append("%s,sha256=%s,%d" % (name, digest.decode(), len(data)))
    record.append(info + "/RECORD,,")
    files.append((info + "/RECORD", ("\n".join(record) + "\n").encode()))
    return files


def _zip(path, files):
    with zipfile.ZipFile(path, "w", zipfile.ZIP_DEFLATED) as z:
        for name, data in files:
            zi = zipfile.ZipInfo(name, EPOCH)
            zi.external_attr = 0o644 << 16
            zi.compress_type = zipfile.ZIP_DEFLATED
            z.writestr(zi, data)


# ---- PEP 517 hooks ----------------------------------------------------------------------

def get_requires_for_build_wheel(config_settings=None):
    return []


def get_requires_for_build_sdist(config_settings=None):
    return []


def prepare_metadata_for_build_wheel(metadata_directory, config_settings=None):
    v = version()
    info = "%s-%s.dist-info" % (DIST, v)
    os.makedirs(os.path.join(metadata_directory, info), exist_ok=True)
    for name, data in _files(v):
        if name.startswith(info + "/") and not name.endswith("/RECORD"):
            with open(os.path.join(metadata_directory, name), "wb") as f:
                f.write(data)
    return info


def build_wheel(wheel_directory, config_settings=None, metadata_directory=None):
    v = version()
    name = "%s-%s-py3-none-any.whl" % (DIST, v)
    os.makedirs(wheel_directory, exist_ok=True)
    _zip(os.path.join(wheel_directory, name), _files(v))
    return name


def build_sdist(sdist_directory, config_settings=None):
    v = version()
    base = "%s-%s" % (DIST, v)
    name = base + ".tar.gz"
    os.makedirs(sdist_directory, exist_ok=True)
    pkg_info = _metadata(v)
    with tarfile.open(os.path.join(sdist_directory, name), "w:gz", format=tarfile.PAX_FORMAT) as t:
        for fn in ("pyproject.toml", "mechd_build.py", "mechd.py", "README.md", "PKG-INFO"):
            data = pkg_info if fn == "PKG-INFO" else _read(fn)
            ti = tarfile.TarInfo(base + "/" + fn)
            ti.size, ti.mtime, ti.mode = len(data), 1577836800, 0o644
            t.addfile(ti, io.BytesIO(data))
    return name


if __name__ == "__main__":
    if len(sys.argv) != 2:
        sys.stderr.write("usage: mechd_build.py OUTPUT-DIR\n")
        sys.exit(2)
    print(os.path.join(sys.argv[1], build_wheel(sys.argv[1])))
