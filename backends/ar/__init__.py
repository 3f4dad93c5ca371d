"""AR: the previewed material on an object standing on an ArUco marker in a photo (or video).

    write_marker(path, marker_id=0, pixels=480) -> Path
    ar_command(photo_path, ir, out_path, options) -> ARReport
    ar_video(video_path, ir, out_path, options) -> ARReport
    composite(photo_bgr, material, options) -> (image_bgr, Pose)

Options (strings): marker_length (0.1; any unit, the scene is relative to it), marker_id (any),
scale (1.0: the object's bounding-sphere diameter in marker lengths), intrinsics ("fx,fy,cx,cy";
default from the image size and fov), fov (60 degrees, horizontal), dist (k1,k2,p1,p2,k3),
mesh (teapot), tier (splitsum), env (studio), shadow (0.65 opacity, 0 = none), material (name or
index of the IR material, default the first), exposure (1.0), msaa (4 for a photo; 0 for a
video: the tone map's edge filter instead, about 3x less time per frame), fresnel, multiscatter.
Errors are ARError subclasses with an `exit_code` (NoMarkerFound 65, PhotoUnreadable 66,
AROptionError 2).
"""

from __future__ import annotations

from .compositor import ARFrame, Compositor, composite, over_photo, render_layer
from .errors import ARError, AROptionError, NoMarkerFound, PhotoUnreadable
from .marker import write_marker
from .options import NAME, OPTIONS, AROptions, camera_matrix, parse_options, pick_material
from .photo import ARReport, ar_command, read_photo, write_image_atomic
from .shadow import ShadowOverlay, footprint
from .video import ar_video

__all__ = [
    "OPTIONS",
    "NAME",
    "ARError",
    "ARFrame",
    "AROptionError",
    "AROptions",
    "ARReport",
    "Compositor",
    "NoMarkerFound",
    "PhotoUnreadable",
    "ShadowOverlay",
    "ar_command",
    "ar_video",
    "camera_matrix",
    "composite",
    "footprint",
    "over_photo",
    "parse_options",
    "pick_material",
    "read_photo",
    "render_layer",
    "write_image_atomic",
    "write_marker",
]
