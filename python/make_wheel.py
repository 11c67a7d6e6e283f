"""Packs the built Python module into a wheel (PEP 427 / PEP 491), with the standard library only.

Run by the build's `wheel` target (cmake/camopt_python.cmake), never by hand:
  make_wheel.py --tag
      prints the wheel tag of this interpreter (cp311-cp311-linux_x86_64), for the file name
  make_wheel.py --stage DIR --version V --out FILE
      zips DIR (the module, its stub and camopt.libs/, already staged with their RUNPATHs set by
      cmake/camopt_wheel_stage.cmake) with camopt-V.dist-info/{METADATA,WHEEL,top_level.txt,RECORD}

The module is the same top-level extension `camopt` as in build/python and in the .deb; the wheel
adds nothing to it but the library it links (camopt.libs/libcamopt.so.N), the OpenCASCADE module
that library opens from its folder when a part needs the kernel (camopt.libs/libcamopt_occt.so,
cad/solid.cc) and the metadata. The
archive is reproducible: sorted entries, fixed timestamps (SOURCE_DATE_EPOCH if set).
"""
import argparse
import base64
import hashlib
import os
import pathlib
import sys
import sysconfig
import time
import zipfile

NAME = "camopt"
SUMMARY = "design optimisation of cam reducers and cam mechanisms"


def wheel_tag():
    """The tag of the interpreter running this script: the one the module was built for."""
    impl = sys.implementation.name
    if impl != "cpython":
        raise SystemExit(f"make_wheel.py: only CPython is supported, not {impl}")
    interpreter = f"cp{sys.version_info.major}{sys.version_info.minor}"
    soabi = sysconfig.get_config_var("SOABI") or ""  # cpython-311-x86_64-linux-gnu
    abi = "cp" + soabi.split("-")[1] if soabi.startswith("cpython-") else interpreter
    platform = sysconfig.get_platform().replace("-", "_").replace(".", "_")  # linux_x86_64
    return f"{interpreter}-{abi}-{platform}"


def record_hash(data):
    digest = hashlib.sha256(data).digest()
    return "sha256=" + base64.urlsafe_b64encode(digest).rstrip(b"=").decode()


def metadata(version):
    major, minor = sys.version_info[:2]
    return (
        "Metadata-Version: 2.1\n"
        f"Name: {NAME}\n"
        f"Version: {version}\n"
        f"Summary: {SUMMARY}\n"
        # The module is built for this interpreter's ABI (the tag says so too).
        f"Requires-Python: =={major}.{minor}.*\n"
        # The module imports NumPy when it loads; pybind11 2.10 (Debian 12) predates NumPy 2's ABI.
        "Requires-Dist: numpy<2\n"
        "Classifier: Programming Language :: Python :: 3\n"
        "Classifier: Programming Language :: C++\n"
        "Classifier: Operating System :: POSIX :: Linux\n"
        "Description-Content-Type: text/plain\n"
        "\n"
        "camopt analyses and sizes lobe cam reducers, cycloid drives, disc cams and globoidal cams\n"
        "from JSON study files. This wheel holds the Python module `camopt` and the library it\n"
        "links; it needs the Debian 12 shared libraries camopt was built against (Ceres, Ipopt,\n"
        "NLopt, SUNDIALS, FFTW, OpenCASCADE, ...: scripts/install_deps.sh --program).\n"
    ).encode()


def wheel_file(tag):
    return (
        "Wheel-Version: 1.0\n"
        "Generator: camopt make_wheel.py\n"
        "Root-Is-Purelib: false\n"
        f"Tag: {tag}\n"
    ).encode()


def pack(stage, version, out):
    stage = pathlib.Path(stage)
    out = pathlib.Path(out)
    tag = wheel_tag()
    expected = f"{NAME}-{version}-{tag}.whl"
    if out.name != expected:
        raise SystemExit(f"make_wheel.py: the wheel of this interpreter is {expected}, not {out.name}")
    suffix = sysconfig.get_config_var("EXT_SUFFIX")
    if not (stage / f"{NAME}{suffix}").is_file():
        raise SystemExit(f"make_wheel.py: no {NAME}{suffix} in {stage} (a module for another Python?)")

    files = []  # (archive name, bytes, executable)
    for p in sorted(stage.rglob("*")):
        if p.is_file():
            files.append((p.relative_to(stage).as_posix(), p.read_bytes(), os.access(p, os.X_OK)))
    dist_info = f"{NAME}-{version}.dist-info"
    files.append((f"{dist_info}/METADATA", metadata(version), False))
    files.append((f"{dist_info}/WHEEL", wheel_file(tag), False))
    files.append((f"{dist_info}/top_level.txt", f"{NAME}\n".encode(), False))
    record = "".join(f"{name},{record_hash(data)},{len(data)}\n" for name, data, _ in files)
    record += f"{dist_info}/RECORD,,\n"
    files.append((f"{dist_info}/RECORD", record.encode(), False))

    epoch = max(int(os.environ.get("SOURCE_DATE_EPOCH", "315532800")), 315532800)  # zip: >= 1980
    stamp = time.gmtime(epoch)[:6]
    out.parent.mkdir(parents=True, exist_ok=True)
    tmp = out.with_name(out.name + ".part")
    with zipfile.ZipFile(tmp, "w", compression=zipfile.ZIP_DEFLATED) as z:
        for name, data, executable in files:
            info = zipfile.ZipInfo(name, date_time=stamp)
            info.compress_type = zipfile.ZIP_DEFLATED
            info.external_attr = (0o100755 if executable else 0o100644) << 16
            z.writestr(info, data)
    os.replace(tmp, out)
    return out


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--tag", action="store_true", help="print this interpreter's wheel tag")
    ap.add_argument("--stage", help="the staged files: camopt<EXT_SUFFIX>, camopt.pyi, camopt.libs/")
    ap.add_argument("--version", help="the project's version (CMake's PROJECT_VERSION)")
    ap.add_argument("--out", help="the wheel to write: DIR/camopt-VERSION-TAG.whl")
    a = ap.parse_args()
    if a.tag:
        print(wheel_tag())
        return
    if not (a.stage and a.version and a.out):
        ap.error("--stage, --version and --out are needed")
    pack(a.stage, a.version, a.out)


if __name__ == "__main__":
    main()
