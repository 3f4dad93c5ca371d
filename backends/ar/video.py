"""`cnlmc ar VIDEO`: every frame composited by one Compositor (what frames share is made once)."""

from __future__ import annotations

import os
from collections.abc import Mapping
from pathlib import Path

from .compositor import Compositor
from .errors import NoMarkerFound, PhotoUnreadable
from .options import IR, parse_options, pick_material
from .photo import ARReport

#: video frames: no multisampling (bench/ar_frames.py: msaa 4 costs about 3x per frame on llvmpipe).
VIDEO_MSAA = "0"


def ar_video(
    video_path: str | Path,
    ir: IR,
    out_path: str | Path,
    options: Mapping[str, object] | None = None,
    max_frames: int | None = None,
) -> ARReport:
    """Frames in, frames out (OpenCV VideoCapture / VideoWriter, mp4v). Frames without a marker
    pass through unchanged and are counted in `missed`; none found at all raises NoMarkerFound."""
    import cv2

    opts = parse_options({"msaa": VIDEO_MSAA, **(options or {})})
    material = pick_material(ir, opts.material)
    with Compositor(opts) as compositor:
        capture = cv2.VideoCapture(str(video_path))
        if not capture.isOpened():
            raise PhotoUnreadable(f"cannot open video {video_path}")
        return _composite_frames(compositor, capture, video_path, material, Path(out_path), max_frames)


def _composite_frames(compositor, capture, video_path, material, out_path: Path, max_frames) -> ARReport:
    import cv2

    fps = capture.get(cv2.CAP_PROP_FPS) or 25.0
    writer, poses, missed, count = None, [], 0, 0
    partial = out_path.with_name(f".{out_path.name}.partial{out_path.suffix}")
    try:
        while max_frames is None or count < max_frames:
            ok, frame = capture.read()
            if not ok:
                break
            count += 1
            try:
                result = compositor.composite(frame, material, source=f"{Path(video_path).name} frame {count}")
                frame, pose = result.image, result.pose
                poses.append(pose)
            except NoMarkerFound:
                missed += 1
            if writer is None:
                out_path.parent.mkdir(parents=True, exist_ok=True)
                writer = cv2.VideoWriter(
                    str(partial), cv2.VideoWriter.fourcc(*"mp4v"), fps, (frame.shape[1], frame.shape[0])
                )
            writer.write(frame)
    finally:
        capture.release()
        if writer is not None:
            writer.release()
    if count == 0 or not poses:
        partial.unlink(missing_ok=True)
    if count == 0:
        raise PhotoUnreadable(f"no frames could be read from {video_path}")
    if not poses:
        raise NoMarkerFound(f"no marker found in any of the {count} frames of {Path(video_path).name}")
    os.replace(partial, out_path)
    return ARReport(out_path, count, poses, missed)
