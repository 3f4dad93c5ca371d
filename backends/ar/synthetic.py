"""Synthetic photos with a marker at a known pose (for tests and documentation images)."""

from __future__ import annotations

import numpy as np

from .marker import marker_image
from .pose import default_intrinsics, marker_object_points


def table_background(width: int, height: int, seed: int = 0) -> np.ndarray:
    """A wooden-table-like BGR background: smooth gradient, streaks and a little noise."""
    rng = np.random.default_rng(seed)
    y, x = np.mgrid[0:height, 0:width].astype(np.float32)
    base = 0.55 + 0.25 * (y / height) + 0.04 * np.sin(x / 23.0 + 3 * np.sin(y / 97.0))
    noise = rng.normal(0, 0.015, (height, width)).astype(np.float32)
    grey = np.clip(base + noise, 0, 1)
    bgr = np.stack([grey * 0.55, grey * 0.68, grey * 0.85], -1)
    return np.round(bgr * 255).astype(np.uint8)


def synthetic_photo(
    rvec,
    tvec,
    width: int = 640,
    height: int = 480,
    marker_length: float = 0.1,
    marker_id: int = 0,
    K: np.ndarray | None = None,
    seed: int = 0,
):
    """(BGR photo, K, true corner pixels (4, 2)) with the marker warped in by its exact homography."""
    import cv2

    K = default_intrinsics(width, height) if K is None else K
    truth, _ = cv2.projectPoints(
        marker_object_points(marker_length), np.asarray(rvec, float), np.asarray(tvec, float), K, np.zeros(5)
    )
    truth = truth.reshape(4, 2)
    square = 480
    image, quiet = marker_image(marker_id, square)
    side = image.shape[0]
    s = square * (side / square)  # the quiet zone is printed too (white paper around)
    # Continuous coordinates of the black square's corners (pixel centres at integers).
    a, b = quiet - 0.5, quiet + square - 0.5
    src = np.array([[a, a], [b, a], [b, b], [a, b]], np.float32)
    H = cv2.getPerspectiveTransform(src, truth.astype(np.float32))
    warped = cv2.warpPerspective(
        image, H, (width, height), flags=cv2.INTER_AREA if s > width else cv2.INTER_LINEAR, borderValue=0
    )
    mask = cv2.warpPerspective(np.full_like(image, 255), H, (width, height), flags=cv2.INTER_LINEAR, borderValue=0)
    photo = table_background(width, height, seed).astype(np.float32)
    alpha = (mask.astype(np.float32) / 255.0)[..., None]
    paper = np.repeat(warped[..., None], 3, axis=2).astype(np.float32) * 0.95
    return np.round(paper * alpha + photo * (1 - alpha)).astype(np.uint8), K, truth
