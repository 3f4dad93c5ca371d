"""Marker detection and camera pose (OpenCV), and the matching OpenGL camera.

Marker frame: origin at the marker centre, x to the right, y up the printed marker, z out of
the paper. The world of the preview scene is y-up; `MARKER_FROM_WORLD` stands it on the
marker: world (x, y, z) -> marker (x, -z, y).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from .errors import NoMarkerFound
from .marker import DICTIONARY_NAME, dictionary

MARKER_FROM_WORLD = np.array([[1, 0, 0, 0], [0, 0, -1, 0], [0, 1, 0, 0], [0, 0, 0, 1]], np.float64)
CV_TO_GL = np.diag([1.0, -1.0, -1.0, 1.0])


@dataclass
class Detection:
    marker_id: int
    corners: np.ndarray  # (4, 2) pixel coordinates: top-left, top-right, bottom-right, bottom-left


@dataclass
class Pose:
    rvec: np.ndarray
    tvec: np.ndarray
    K: np.ndarray
    dist: np.ndarray
    marker_length: float

    @property
    def rotation(self) -> np.ndarray:
        import cv2

        return cv2.Rodrigues(self.rvec)[0]

    def camera_from_marker(self) -> np.ndarray:
        m = np.eye(4)
        m[:3, :3], m[:3, 3] = self.rotation, np.ravel(self.tvec)
        return m

    def project(self, points_marker: np.ndarray) -> np.ndarray:
        import cv2

        pts, _ = cv2.projectPoints(
            np.ascontiguousarray(points_marker, np.float64).reshape(-1, 3), self.rvec, self.tvec, self.K, self.dist
        )
        return pts.reshape(-1, 2)


def default_intrinsics(width: int, height: int, fov_x_deg: float = 60.0) -> np.ndarray:
    """A pinhole camera for an image of this size: principal point at the centre, given FOV."""
    f = (width / 2) / math.tan(math.radians(fov_x_deg) / 2)
    return np.array([[f, 0, (width - 1) / 2], [0, f, (height - 1) / 2], [0, 0, 1]], np.float64)


def marker_object_points(length: float) -> np.ndarray:
    """The corners in SOLVEPNP_IPPE_SQUARE order, in the marker frame."""
    h = length / 2
    return np.array([[-h, h, 0], [h, h, 0], [h, -h, 0], [-h, -h, 0]], np.float64)


def detect(image: np.ndarray, name: str = DICTIONARY_NAME) -> list[Detection]:
    import cv2

    grey = image if image.ndim == 2 else cv2.cvtColor(image, cv2.COLOR_BGR2GRAY)
    params = cv2.aruco.DetectorParameters()
    params.cornerRefinementMethod = cv2.aruco.CORNER_REFINE_SUBPIX
    corners, ids, _ = cv2.aruco.ArucoDetector(dictionary(name), params).detectMarkers(grey)
    if ids is None or len(ids) == 0:
        return []
    return [Detection(int(i), np.asarray(c, np.float64).reshape(4, 2)) for i, c in zip(np.ravel(ids), corners)]


def find_marker(image: np.ndarray, marker_id: int | None = None, source: str = "the image") -> Detection:
    found = detect(image)
    if marker_id is not None:
        found = [d for d in found if d.marker_id == marker_id]
    if not found:
        which = f"marker {marker_id}" if marker_id is not None else "marker"
        raise NoMarkerFound(f"no {which} found in {source} (ArUco {DICTIONARY_NAME}; print one with `write_marker`)")
    return max(found, key=lambda d: abs(_area(d.corners)))


def _area(c: np.ndarray) -> float:
    x, y = c[:, 0], c[:, 1]
    return 0.5 * float(np.dot(x, np.roll(y, -1)) - np.dot(y, np.roll(x, -1)))


def estimate_pose(detection: Detection, marker_length: float, K: np.ndarray, dist=None) -> Pose:
    import cv2

    dist = np.zeros(5) if dist is None else np.asarray(dist, np.float64)
    ok, rvec, tvec = cv2.solvePnP(
        marker_object_points(marker_length), detection.corners, K, dist, flags=cv2.SOLVEPNP_IPPE_SQUARE
    )
    if not ok:
        raise NoMarkerFound("the marker was found but its pose could not be estimated")
    return Pose(rvec, tvec, K, dist, marker_length)


def gl_projection(K: np.ndarray, width: int, height: int, near: float, far: float) -> np.ndarray:
    """OpenGL projection matching the pinhole K for an image read back top row first.
    OpenCV puts pixel centres at integers, OpenGL at +0.5: hence the +0.5 shifts."""
    fx, fy, cx, cy = K[0, 0], K[1, 1], K[0, 2], K[1, 2]
    p = np.zeros((4, 4))
    p[0, 0], p[0, 2] = 2 * fx / width, 1 - 2 * (cx + 0.5) / width
    p[1, 1], p[1, 2] = 2 * fy / height, 2 * (cy + 0.5) / height - 1
    p[2, 2], p[2, 3] = (far + near) / (near - far), 2 * far * near / (near - far)
    p[3, 2] = -1.0
    return p


def gl_view(pose: Pose) -> np.ndarray:
    """World (y-up, object frame) -> OpenGL eye coordinates."""
    return CV_TO_GL @ pose.camera_from_marker() @ MARKER_FROM_WORLD


def project_gl(view_projection: np.ndarray, points: np.ndarray, width: int, height: int) -> np.ndarray:
    """World points -> pixel coordinates (OpenCV convention) through the OpenGL matrices."""
    p = np.hstack([np.asarray(points, np.float64), np.ones((len(points), 1))]) @ view_projection.T
    ndc = p[:, :2] / p[:, 3:4]
    return np.stack([(ndc[:, 0] + 1) * width / 2 - 0.5, (1 - ndc[:, 1]) * height / 2 - 0.5], 1)
