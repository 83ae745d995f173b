"""scbt.lift_boundary_to_3d on a tilted disk rendered with numpy: accuracy with noisy depth and
20 % of the outline's depth missing, and clear errors for bad input."""

import math

import numpy as np
import pytest

import scbt

FX, FY, CX, CY = 525.0, 525.0, 319.5, 239.5


def disk_scene(centre, normal, radius, noise=0.0, missing=0.0, seed=0):
    """Depth (uint16 mm) of a disk in front of a 2 m wall, its projected outline, and truth."""
    rng = np.random.default_rng(seed)
    normal = np.asarray(normal, float) / np.linalg.norm(normal)
    centre = np.asarray(centre, float)
    ys, xs = np.mgrid[0:480, 0:640].astype(float)
    rays = np.stack([(xs - CX) / FX, (ys - CY) / FY, np.ones_like(xs)], -1)
    z = normal.dot(centre) / (rays @ normal)
    on_disk = np.linalg.norm(z[..., None] * rays - centre, axis=-1) <= radius
    depth = np.where(on_disk, z, 2.0)
    depth = depth + rng.normal(0, 1, depth.shape) * noise * depth**2
    u = np.cross(normal, [1.0, 0.0, 0.0])
    u /= np.linalg.norm(u)
    v = np.cross(normal, u)
    angles = np.linspace(0, 2 * np.pi, 72, endpoint=False)
    rim = centre + radius * (np.cos(angles)[:, None] * u + np.sin(angles)[:, None] * v)
    outline = np.stack([FX * rim[:, 0] / rim[:, 2] + CX, FY * rim[:, 1] / rim[:, 2] + CY], 1)
    depth_mm = np.round(depth * 1000).astype(np.uint16)
    if missing:  # one arc of the outline loses its depth
        lost = outline[: int(missing * len(outline))]
        for x, y in lost:
            depth_mm[max(0, int(y) - 8) : int(y) + 9, max(0, int(x) - 8) : int(x) + 9] = 0
    return depth_mm, outline, centre, normal


def test_recovers_centroid_normal_and_radius_with_noise_and_missing_depth():
    centre, normal = [0.03, -0.02, 0.6], [0.0, -0.7, -0.7]
    depth, outline, true_centre, true_normal = disk_scene(
        centre, normal, 0.1, noise=0.0016, missing=0.2, seed=3)
    rim = scbt.lift_boundary_to_3d(outline, depth, (FX, FY, CX, CY))
    assert rim.valid
    assert 0 < rim.n_valid < rim.n_samples
    assert np.linalg.norm(rim.centroid - true_centre) < 0.003
    angle = math.degrees(math.acos(min(1.0, float(rim.normal @ true_normal))))
    assert angle < 2.0
    assert rim.circle_found and abs(rim.circle_radius - 0.1) < 0.002
    assert rim.points.shape == (rim.n_samples, 3) and rim.samples.shape == (rim.n_samples, 2)
    assert np.isnan(rim.points[:, 0]).sum() == rim.n_samples - rim.n_valid
    # The same in float metres, and with a 3x3 camera matrix.
    K = np.array([[FX, 0, CX], [0, FY, CY], [0, 0, 1]])
    again = scbt.lift_boundary_to_3d(outline, depth.astype(np.float32) / 1000, K)
    assert np.allclose(again.centroid, rim.centroid, atol=1e-4)


def test_projection_round_trip_and_no_depth_is_invalid():
    pixels = scbt.project_points(np.array([[0.1, -0.05, 0.8]]), (FX, FY, CX, CY))
    assert np.allclose(pixels, [[CX + FX * 0.125, CY - FY * 0.0625]])
    _, outline, _, _ = disk_scene([0, 0, 0.8], [0, -0.5, -1], 0.08)
    rim = scbt.lift_boundary_to_3d(outline, np.zeros((480, 640), np.uint16), (FX, FY, CX, CY))
    assert not rim.valid and rim.n_valid == 0


def test_samples_are_bounded_by_the_image_not_the_boundarys_extent():
    depth, outline, _, _ = disk_scene([0, 0, 0.8], [0, -0.5, -1], 0.08)
    middle = np.array([CX, CY])
    # Grown 1000 times about the image centre: 72 vertices, none near the image, and no point
    # along edges some 4e5 px long (they took memory in proportion: 1e5 times took gigabytes).
    far = middle + (outline - middle) * 1e3
    rim = scbt.lift_boundary_to_3d(far, depth, (FX, FY, CX, CY))
    assert rim.n_samples == len(outline) and not rim.valid
    # Half of it in the image: the points along its edges stop near the image's border.
    shifted = outline + [300, 0]
    rim = scbt.lift_boundary_to_3d(shifted, depth, (FX, FY, CX, CY))
    beyond = rim.samples[:, 0] > 640 + 10
    assert 0 < beyond.sum() <= (shifted[:, 0] > 640 + 10).sum()


def test_clear_errors_for_bad_input():
    depth, outline, _, _ = disk_scene([0, 0, 0.8], [0, -0.5, -1], 0.08)
    camera = (FX, FY, CX, CY)
    with pytest.raises(TypeError, match="uint16"):
        scbt.lift_boundary_to_3d(outline, depth.astype(np.int32), camera)
    with pytest.raises(ValueError, match="shape"):
        scbt.lift_boundary_to_3d(outline, np.zeros((4, 4, 3), np.uint16), camera)
    with pytest.raises(ValueError, match="boundary"):
        scbt.lift_boundary_to_3d(outline[:, :1], depth, camera)
    with pytest.raises(ValueError, match="intrinsics"):
        scbt.lift_boundary_to_3d(outline, depth, (FX, FY, CX))
    with pytest.raises(ValueError, match="fx"):
        scbt.lift_boundary_to_3d(outline, depth, (-1.0, FY, CX, CY))
    with pytest.raises(ValueError, match="sample_step"):
        scbt.lift_boundary_to_3d(outline, depth, camera, sample_step=0)
    with pytest.raises(TypeError, match="unknown depth option"):
        scbt.lift_boundary_to_3d(outline, depth, camera, sample_stepp=2)
    with pytest.raises(ValueError, match="cannot open"):
        scbt.read_camera_info("/nonexistent/camera.yaml")


def test_reads_ros_camera_info(tmp_path):
    path = tmp_path / "camera.yaml"
    path.write_text(
        "camera_matrix:\n  rows: 3\n  cols: 3\n  data: [520, 0, 320, 0, 521, 240, 0, 0, 1]\n"
        "distortion_model: plumb_bob\n"
        "distortion_coefficients:\n  rows: 1\n  cols: 5\n  data: [0.1, 0, 0, 0, 0]\n")
    info = scbt.read_camera_info(str(path))
    assert info["intrinsics"] == (520.0, 521.0, 320.0, 240.0)
    assert info["distortion"] == [0.1, 0.0, 0.0, 0.0, 0.0]
