"""AR: detection and pose on synthetic photos land within 2 px; the rendered object sits on
the marker; clear errors; marker PNGs; video frames."""

from __future__ import annotations

import numpy as np
import pytest

from tests.helpers import require

cv2 = require("cv2", "ar")
pytestmark = pytest.mark.cv2

from cnlmc.backends.ar import (  # noqa: E402
    AROptionError,
    NoMarkerFound,
    PhotoUnreadable,
    ar_command,
    ar_video,
    composite,
    parse_options,
    write_marker,
)
from cnlmc.backends.ar.pose import (  # noqa: E402
    MARKER_FROM_WORLD,
    Pose,
    detect,
    estimate_pose,
    find_marker,
    marker_object_points,
    project_gl,
)

from .conftest import MARKER_LENGTH  # noqa: E402

TOLERANCE_PX = 2.0


def base_ring(radius: float = 0.5, n: int = 16) -> np.ndarray:
    """Points on the ground circle of the fitted object (world, y-up), scaled like the AR model."""
    t = np.linspace(0, 2 * np.pi, n, endpoint=False)
    return np.stack([radius * np.cos(t), np.zeros(n), radius * np.sin(t)], 1)


def world_to_marker(points: np.ndarray, scale: float) -> np.ndarray:
    return (np.hstack([points * scale, np.ones((len(points), 1))]) @ MARKER_FROM_WORLD.T)[:, :3]


def test_detected_corners_match_the_truth(posed_photo):
    found = detect(posed_photo["photo"])
    assert [d.marker_id for d in found] == [0]
    error = np.linalg.norm(found[0].corners - posed_photo["truth"], axis=1)
    assert error.max() < TOLERANCE_PX, (posed_photo["name"], error)


def test_pose_reprojects_corners_and_the_object_base(posed_photo):
    p = posed_photo
    pose = estimate_pose(find_marker(p["photo"]), MARKER_LENGTH, p["K"])
    truth_pose = Pose(p["rvec"].reshape(3, 1), p["tvec"].reshape(3, 1), p["K"], np.zeros(5), MARKER_LENGTH)
    corners = marker_object_points(MARKER_LENGTH)
    assert np.linalg.norm(pose.project(corners) - truth_pose.project(corners), axis=1).max() < TOLERANCE_PX
    base = world_to_marker(base_ring(), MARKER_LENGTH / 2)
    assert np.linalg.norm(pose.project(base) - truth_pose.project(base), axis=1).max() < TOLERANCE_PX


def test_opengl_matrices_match_opencv_projection(posed_photo, gl_available, gold):
    """The render's view-projection puts world points exactly where OpenCV projects them."""
    p = posed_photo
    frame = composite(p["photo"], gold["materials"][0], {"mesh": "sphere", "tier": "analytic", "msaa": "1"})
    h, w = p["photo"].shape[:2]
    points = np.vstack([base_ring(), [[0, 0, 0], [0, 1, 0], [0.3, 0.5, -0.2]]])
    gl_px = project_gl(frame.view_projection @ frame.model, points, w, h)
    cv_px = frame.pose.project(world_to_marker(points, MARKER_LENGTH / 2))
    assert np.abs(gl_px - cv_px).max() < 0.01


def test_rendered_object_stands_on_the_marker(posed_photo, gl_available, gold):
    """The rendered sphere's silhouette matches the truth: its centre (projected sphere centre,
    a point the silhouette must cover) and its extent within 2 px."""
    p = posed_photo
    opts = {"mesh": "sphere", "tier": "analytic", "shadow": "0", "msaa": "4"}
    frame = composite(p["photo"], gold["materials"][0], opts)
    truth_pose = Pose(p["rvec"].reshape(3, 1), p["tvec"].reshape(3, 1), p["K"], np.zeros(5), MARKER_LENGTH)
    centre = truth_pose.project(world_to_marker(np.array([[0.0, 1.0, 0.0]]), MARKER_LENGTH / 2))[0]
    alpha = frame.rgba[..., 3] > 127
    ys, xs = np.nonzero(alpha)
    assert alpha[int(round(centre[1])), int(round(centre[0]))]
    # The silhouette of a sphere projects to an ellipse whose centre is close to the projected
    # centre for these narrow fields of view; compare the mask centroid.
    centroid = np.array([xs.mean(), ys.mean()])
    assert np.linalg.norm(centroid - centre) < TOLERANCE_PX + 1.0, (p["name"], centroid, centre)


def test_composite_changes_only_the_object_and_shadow(posed_photo, gl_available, gold):
    frame = composite(posed_photo["photo"], gold["materials"][0], {"mesh": "teapot", "tier": "analytic"})
    changed = np.any(frame.image != posed_photo["photo"], axis=2)
    assert 0.002 < changed.mean() < 0.5
    assert np.array_equal(frame.image[frame.rgba[..., 3] == 0], posed_photo["photo"][frame.rgba[..., 3] == 0])


def test_no_marker_is_a_clear_error(tmp_path, gold):
    blank = tmp_path / "photo.jpg"
    cv2.imwrite(str(blank), np.full((240, 320, 3), 128, np.uint8))
    with pytest.raises(NoMarkerFound, match="no marker found in photo.jpg") as info:
        ar_command(blank, gold, tmp_path / "out.png")
    assert info.value.exit_code == 65
    with pytest.raises(PhotoUnreadable) as info:
        ar_command(tmp_path / "missing.jpg", gold, tmp_path / "out.png")
    assert info.value.exit_code == 66
    (tmp_path / "junk.jpg").write_bytes(b"not an image")
    with pytest.raises(PhotoUnreadable):
        ar_command(tmp_path / "junk.jpg", gold, tmp_path / "out.png")
    with pytest.raises(AROptionError) as info:
        parse_options({"marker_length": "-1"})
    assert info.value.exit_code == 2


def test_marker_png_round_trip(tmp_path):
    path = write_marker(tmp_path / "marker.png", marker_id=7, pixels=300)
    image = cv2.imread(str(path))
    found = detect(image)
    assert [d.marker_id for d in found] == [7]
    with pytest.raises(AROptionError):
        write_marker(tmp_path / "bad.png", marker_id=99)


def test_photo_command_and_video(tmp_path, gl_available, gold):
    from cnlmc.backends.ar.synthetic import synthetic_photo

    frames = [
        synthetic_photo(np.array([2.2, 0.3 + 0.05 * i, -0.2]), np.array([0.0, 0.02, 0.5]), 320, 240)[0]
        for i in range(3)
    ]
    photo = tmp_path / "photo.png"
    cv2.imwrite(str(photo), frames[0])
    report = ar_command(photo, gold, tmp_path / "ar.png", {"tier": "analytic"})
    assert report.path.exists() and cv2.imread(str(report.path)).shape == (240, 320, 3)
    video = tmp_path / "in.mp4"
    writer = cv2.VideoWriter(str(video), cv2.VideoWriter_fourcc(*"mp4v"), 10, (320, 240))
    if not writer.isOpened():
        pytest.skip("no mp4v encoder in this OpenCV build")
    for f in frames + [np.full_like(frames[0], 90)]:
        writer.write(f)
    writer.release()
    report = ar_video(video, gold, tmp_path / "out.mp4", {"tier": "analytic"})
    assert report.frames == 4 and report.missed == 1 and len(report.poses) == 3
    capture = cv2.VideoCapture(str(tmp_path / "out.mp4"))
    assert int(capture.get(cv2.CAP_PROP_FRAME_COUNT)) == 4
    capture.release()


def test_tone_map_rectangle_holds_object_and_shadow(posed_photo, gl_available, gold, monkeypatch):
    """The AR layer's tone map runs over the object's and the shadow's rectangle only; the
    composite is the same as with the whole frame tone mapped."""
    from cnlmc.backends.preview.render import Renderer

    opts = {"mesh": "teapot", "tier": "splitsum", "shadow": "0.6"}
    clipped = composite(posed_photo["photo"], gold["materials"][0], opts).image
    monkeypatch.setattr(Renderer, "drawn_rect", lambda self, *a, **k: None)
    whole = composite(posed_photo["photo"], gold["materials"][0], opts).image
    assert np.abs(clipped.astype(int) - posed_photo["photo"].astype(int)).max() > 50  # something drawn
    np.testing.assert_array_equal(clipped, whole)


def test_over_photo_blends_only_where_the_layer_is():
    from cnlmc.backends.ar import over_photo

    rng = np.random.default_rng(3)
    photo = rng.integers(0, 256, (40, 60, 3), dtype=np.uint8)
    rgba = np.zeros((40, 60, 4), np.uint8)
    rgba[10:25, 5:30] = rng.integers(0, 256, (15, 25, 4), dtype=np.uint8)
    a = rgba[..., 3:4] / 255.0
    expected = np.round(rgba[..., 2::-1] * a + photo * (1 - a)).astype(np.uint8)
    np.testing.assert_array_equal(over_photo(rgba, photo), expected)
    empty = over_photo(np.zeros_like(rgba), photo)
    np.testing.assert_array_equal(empty, photo)
    assert empty is not photo


def test_shadow_footprint_is_made_once_per_mesh(posed_photo, gl_available, gold, monkeypatch):
    import cnlmc.backends.ar as ar
    from cnlmc.backends.ar import shadow

    made = []
    original = shadow.footprint
    monkeypatch.setattr(shadow, "footprint", lambda mesh, *a, **k: made.append(1) or original(mesh, *a, **k))
    with ar.Compositor({"mesh": "teapot", "tier": "analytic"}) as compositor:  # what a video uses
        for _ in range(3):
            compositor.composite(posed_photo["photo"], gold["materials"][0])
    assert len(made) == 1


def test_video_frames_default_to_no_multisampling(tmp_path, monkeypatch, gold):
    import cnlmc.backends.ar as ar
    from cnlmc.backends.ar.synthetic import synthetic_photo

    video = tmp_path / "in.mp4"
    writer = cv2.VideoWriter(str(video), cv2.VideoWriter_fourcc(*"mp4v"), 10, (160, 120))
    if not writer.isOpened():
        pytest.skip("no mp4v encoder in this OpenCV build")
    writer.write(synthetic_photo(np.array([2.2, 0.3, -0.2]), np.array([0.0, 0.02, 0.5]), 160, 120)[0])
    writer.release()
    seen = []
    monkeypatch.setattr(
        ar.Compositor,
        "composite",
        lambda self, frame, material, source: (
            seen.append(self.opts.msaa) or (_ for _ in ()).throw(NoMarkerFound("skip"))
        ),
    )
    with pytest.raises(NoMarkerFound):
        ar_video(video, gold, tmp_path / "a.mp4", {"tier": "analytic"})
    with pytest.raises(NoMarkerFound):
        ar_video(video, gold, tmp_path / "b.mp4", {"tier": "analytic", "msaa": "4"})
    assert seen == [0, 4]
