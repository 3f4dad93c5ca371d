"""Frame rate of AR on this machine: a marker moving through synthetic photos, each frame
detected, posed, rendered (llvmpipe) and composited, as `cnlmc ar` does for every video frame.

    .venv/bin/python bench/ar_frames.py [--sizes 640x480,1280x720] [--frames 30] [--mesh teapot] [--msaa 0]

Per stage, median ms over the frames (after one warm-up frame, which compiles the shader):
detection (OpenCV's ArUco detector, the peer in this process), pose, render of the layer
(object + contact shadow), read-back, composite; then the whole frame, fps, and the ratio of
the whole frame to OpenCV's detection alone. The paper shows its AR at 50 fps on a GPU.
"""

from __future__ import annotations

import argparse
import sys
import time

import numpy as np


def orbit(frames: int) -> list[tuple[np.ndarray, np.ndarray]]:
    """(rvec, tvec) of a marker seen from a camera circling it at 45-60 degrees of elevation."""
    import cv2

    poses = []
    for i in range(frames):
        turn = 2 * np.pi * i / frames
        tilt = np.radians(40 + 10 * np.sin(turn))
        r_tilt, _ = cv2.Rodrigues(np.array([np.pi - tilt, 0.0, 0.0]))
        r_turn, _ = cv2.Rodrigues(np.array([0.0, 0.0, turn]))
        rvec, _ = cv2.Rodrigues(r_tilt @ r_turn)
        poses.append((rvec.ravel(), np.array([0.01 * np.cos(turn), 0.01 * np.sin(turn), 0.42])))
    return poses


def stage_times(photo: np.ndarray, material: dict, compositor) -> dict[str, float]:
    from cnlmc.backends.ar import camera_matrix, over_photo
    from cnlmc.backends.ar.pose import detect, estimate_pose, find_marker

    opts = compositor.opts

    height, width = photo.shape[:2]
    t0 = time.perf_counter()
    detect(photo)
    t1 = time.perf_counter()
    K = camera_matrix(opts, width, height)
    pose = estimate_pose(find_marker(photo), opts.marker_length, K, opts.dist)
    t2 = time.perf_counter()
    rgba, _, _ = compositor.render_layer(pose, width, height, material)
    t3 = time.perf_counter()
    over_photo(rgba, photo)
    t4 = time.perf_counter()
    # find_marker detects again: the pose stage is its time minus one detection
    detect_ms = (t1 - t0) * 1e3
    return {
        "detect": detect_ms,
        "pose": max((t2 - t1) * 1e3 - detect_ms, 0.0),
        "render": (t3 - t2) * 1e3,
        "composite": (t4 - t3) * 1e3,
    }


def whole_frame_ms(photo: np.ndarray, material: dict, compositor) -> float:
    start = time.perf_counter()
    compositor.composite(photo, material)
    return (time.perf_counter() - start) * 1e3


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--sizes", default="640x480,1280x720")
    parser.add_argument("--frames", type=int, default=30)
    parser.add_argument("--mesh", default="teapot")
    parser.add_argument("--tier", default="splitsum")
    parser.add_argument("--phrase", default="lightly brushed, blue anodized aluminum")
    parser.add_argument("--msaa", default="", help="samples per pixel (default: the AR default)")
    args = parser.parse_args(argv)
    from cnlmc.api import compile_source
    from cnlmc.backends.ar import Compositor, parse_options
    from cnlmc.backends.ar.synthetic import synthetic_photo

    material = compile_source(args.phrase + "\n").ir["materials"][0]
    opts = parse_options({"mesh": args.mesh, "tier": args.tier, **({"msaa": args.msaa} if args.msaa else {})})
    print(f"{args.phrase!r} on the {args.mesh}, tier {args.tier}, msaa {opts.msaa}, {args.frames} frames per size")
    print(
        f"{'size':>10s} {'detect':>7s} {'pose':>6s} {'render':>7s} {'composite':>9s} {'frame':>7s} {'fps':>5s} "
        f"{'frame/detect':>12s}"
    )
    for size in args.sizes.split(","):
        width, height = (int(x) for x in size.split("x"))
        photos = [synthetic_photo(r, t, width, height, seed=i)[0] for i, (r, t) in enumerate(orbit(args.frames))]
        with Compositor(opts) as compositor:  # what a video keeps from frame to frame
            whole_frame_ms(photos[0], material, compositor)  # warm-up: compile, tables
            stages = [stage_times(p, material, compositor) for p in photos]
            frames = [whole_frame_ms(p, material, compositor) for p in photos]
        med = {k: float(np.median([s[k] for s in stages])) for k in stages[0]}
        frame = float(np.median(frames))
        print(
            f"{size:>10s} {med['detect']:7.1f} {med['pose']:6.1f} {med['render']:7.1f} {med['composite']:9.1f} "
            f"{frame:7.1f} {1000 / frame:5.1f} {frame / med['detect']:12.1f}"
        )
    return 0


if __name__ == "__main__":
    sys.exit(main())
