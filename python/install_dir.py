"""Prints where `cmake --install` puts the tailor package, relative to the prefix (argv[1]):
the entry of this interpreter's sys.path under that prefix (Debian's dist-packages), else
the prefix's lib/python3.X/site-packages (found through PYTHONPATH)."""

import os
import sys
import sysconfig

prefix = os.path.normpath(sys.argv[1])
version = f"python{sys.version_info.major}.{sys.version_info.minor}"
candidates = [
    os.path.normpath(p) for p in sys.path
    if p.endswith(("site-packages", "dist-packages"))
    and os.path.normpath(p).startswith(prefix + os.sep + "lib" + os.sep)
]
# The version-specific folder first (the one a local install is meant for).
candidates.sort(key=lambda p: version not in p)
if candidates:
    print(os.path.relpath(candidates[0], prefix))
else:
    path = sysconfig.get_path("platlib", "posix_prefix", vars={"base": prefix, "platbase": prefix})
    print(os.path.relpath(path, prefix))
