"""Loads the Khronos ANARI API definitions (JSON) into one merged model.

Shared by every generator in this folder so headers, tests and device
introspection tables are all derived from the same reading of the JSON.
"""
import json
import os
import shutil
import subprocess
import sys


class Api:
    """Merged view of anari_core_1_0.json plus every extension's C additions."""

    def __init__(self, api_dir):
        self.api_dir = api_dir
        core = self._load("anari_core_1_0.json")
        self.enums = [dict(e, values=list(e["values"])) for e in core["enums"]]
        self.opaque_types = core["opaqueTypes"]
        self.function_typedefs = list(core["functionTypedefs"])
        self.structs = core["structs"]
        self.functions = core["functions"]
        # Extensions may add enum values and typedefs (frame completion
        # callback); fold them in so the header has the full C surface.
        for name in sorted(os.listdir(api_dir)):
            if not name.endswith(".json") or name == "anari_core_1_0.json":
                continue
            ext = self._load(name)
            for ext_enum in ext.get("enums", []):
                target = self.enum(ext_enum["name"])
                target["values"].extend(ext_enum["values"])
            self.function_typedefs.extend(ext.get("functionTypedefs", []))

    def _load(self, name):
        with open(os.path.join(self.api_dir, name)) as f:
            return json.load(f)

    def enum(self, name):
        return next(e for e in self.enums if e["name"] == name)

    def data_types(self):
        return self.enum("ANARIDataType")["values"]

    def definition_files(self):
        """(file stem, parsed JSON) of every object/extension definition."""
        out = []
        for name in sorted(os.listdir(self.api_dir)):
            if name.endswith(".json") and name != "anari_core_1_0.json":
                out.append((name[:-5], self._load(name)))
        return out


VENDORED_API = os.path.join("third_party", "anari-api")


def api_dir_and_root(argv, usage):
    """(API_DIR, REPO_ROOT) from `[API_DIR] REPO_ROOT`; API_DIR defaults to
    the definitions vendored in the repository."""
    if len(argv) == 2:
        return os.path.join(argv[1], VENDORED_API), argv[1]
    if len(argv) == 3:
        return argv[1], argv[2]
    raise SystemExit(usage)


def handle_class_name(opaque_name):
    """ANARIArray1D -> Array1D (the C++ tag struct in anari::api)."""
    return opaque_name[len("ANARI"):]


def write_source(root, relative_path, text):
    """Writes a generated file, formatted with the repository's clang-format
    style when clang-format is available, so regenerating is byte-stable."""
    path = os.path.join(root, relative_path)
    os.makedirs(os.path.dirname(path), exist_ok=True)
    with open(path, "w") as f:
        f.write(text)
    clang_format = shutil.which("clang-format")
    if clang_format:
        subprocess.run([clang_format, "-i", "--style=file", path], cwd=root,
                       check=True)
    else:
        print("clang-format not found: %s left unformatted" % relative_path,
              file=sys.stderr)
