"""The result cache of scripts/tidy.sh: a file that clang-tidy found clean is not checked again
while nothing it depends on has changed.

    tidy_cache.py keys BUILD_DIR CACHE_DIR TIDY_VERSION FILE...   prints "FILE<TAB>KEY" per FILE
                                                                  whose KEY is not in CACHE_DIR
    tidy_cache.py mark CACHE_DIR KEY...                           records KEYs as clean

A file's key hashes what its findings depend on: the clang-tidy version, .clang-tidy, the file's
compile command (with the checkout's path taken out, so that clones share keys), and the path
and content of every header it includes (the compiler's -MM list). Only clean results are kept:
a file with findings is checked on every run, so a finding is never hidden.
"""

import concurrent.futures
import hashlib
import json
import os
import pathlib
import shlex
import subprocess
import sys


def dependencies(entry):
    """The files the translation unit reads, from the compiler's own -MM list."""
    arguments = shlex.split(entry["command"])
    kept, skip = [], False
    for argument in arguments:  # drop the output and dependency-file options, keep the rest
        if skip:
            skip = False
            continue
        if argument in ("-o", "-MF", "-MT", "-MQ"):
            skip = True
            continue
        if argument in ("-MD", "-MMD"):
            continue
        kept.append(argument)
    result = subprocess.run(kept + ["-MM", "-MG"], cwd=entry["directory"], capture_output=True, text=True)
    if result.returncode != 0:
        return None  # let clang-tidy report whatever is wrong
    words = result.stdout.replace("\\\n", " ").split()
    return sorted({word for word in words[1:]})  # words[0] is the target "x.o:"


def key(entry, root, salt):
    files = dependencies(entry)
    if files is None:
        return None
    digest = hashlib.sha256(salt)
    digest.update(entry["command"].replace(root, "").encode())
    for name in files:
        path = pathlib.Path(entry["directory"], name).resolve()
        digest.update(str(path).replace(root, "").encode())
        try:
            digest.update(hashlib.sha256(path.read_bytes()).digest())
        except OSError:
            return None
    return digest.hexdigest()


def main():
    if sys.argv[1] == "mark":
        cache = pathlib.Path(sys.argv[2])
        cache.mkdir(parents=True, exist_ok=True)
        for name in sys.argv[3:]:
            (cache / name).touch()
        return
    build, cache, version = sys.argv[2], pathlib.Path(sys.argv[3]), sys.argv[4]
    root = str(pathlib.Path.cwd().resolve())
    salt = (version + "\n").encode() + pathlib.Path(".clang-tidy").read_bytes()
    entries = {str(pathlib.Path(e["file"]).resolve()): e for e in json.loads(pathlib.Path(build, "compile_commands.json").read_text())}
    files = sys.argv[5:]

    def key_of(name):  # None for a file without a compile command: clang-tidy then says why
        entry = entries.get(str(pathlib.Path(name).resolve()))
        return key(entry, root, salt) if entry else None

    with concurrent.futures.ThreadPoolExecutor(os.cpu_count() or 2) as pool:
        keys = list(pool.map(key_of, files))
    for name, value in zip(files, keys):
        if value is None or not (cache / value).exists():
            print(f"{name}\t{value or 'none'}")


if __name__ == "__main__":
    main()
