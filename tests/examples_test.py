#!/usr/bin/env python3
"""examples/cpp and examples/python on a rendered clip whose frames come in every format `scbt
track` reads from a folder, in turn (jpg, JPEG, png, bmp, tif, TIFF, ppm, pgm, webp), numbered
without zero padding (so that name order is not frame order): both must track it.

    examples_test.py CPP_TRACK_FOLDER PYTHONPATH
"""
import os
import pathlib
import subprocess
import sys
import tempfile

ROOT = pathlib.Path(__file__).resolve().parent.parent
FORMATS = "jpg,JPEG,png,bmp,tif,TIFF,ppm,pgm,webp"


def run(command, out, env=None):
    with open(out, "w") as stdout:
        done = subprocess.run(command, stdout=stdout, stderr=subprocess.PIPE, text=True, env=env)
    if done.returncode != 0:
        sys.exit(f"examples_test: {' '.join(map(str, command))} exited {done.returncode}:\n"
                 f"{done.stderr}")


def main():
    cpp_example, pythonpath = sys.argv[1], sys.argv[2]
    with tempfile.TemporaryDirectory() as work:
        clip = pathlib.Path(work) / "clip"
        subprocess.run([sys.executable, ROOT / "scripts/render_frames.py", clip, "--frames", "27",
                        "--formats", FORMATS], check=True)
        for frame in clip.iterdir():
            if frame.stem.isdigit():
                frame.rename(frame.with_name(f"{int(frame.stem)}{frame.suffix}"))
        for name, command, env in [
            ("examples/cpp", [cpp_example], None),
            ("examples/python", [sys.executable, ROOT / "examples/python/track_folder.py"],
             dict(os.environ, PYTHONPATH=pythonpath)),
        ]:
            out = pathlib.Path(work) / "boundaries.txt"
            run(command + [clip, clip / "init.txt"], out, env)
            subprocess.run([sys.executable, ROOT / "scripts/check_boundaries.py", out,
                            clip / "truth.txt"], check=True)
            print(f"examples_test: {name} tracked all 27 frames ({FORMATS})")


if __name__ == "__main__":
    main()
