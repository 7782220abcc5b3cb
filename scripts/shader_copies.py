"""Copies of shaders/ with text edits, read through CUBE_SHADER_DIR by the measurement scripts
(shader_parts.sh, ideal_fragments.sh). Imported from the project root, without bytecode:

    sys.dont_write_bytecode = True; sys.path.insert(0, "scripts")
    from shader_copies import write_copies
"""
import pathlib
import shutil
import sys


def write_copies(work, variants, who):
    """Each variant of `variants` ({name: [(file, text there exactly once, replacement)]}) becomes
    work/name: shaders/ with its edits. Stops loudly, naming `who`, where a shader no longer
    matches its edit."""
    work = pathlib.Path(work)
    for name, changes in variants.items():
        folder = work / name
        shutil.copytree("shaders", folder)
        for file, old, new in changes:
            path = folder / file
            text = path.read_text()
            if text.count(old) != 1:
                sys.exit(f"{who}: {file}: expected exactly one '{old.strip()}'")
            path.write_text(text.replace(old, new))
