"""The classes added for today's Ikaros 3 (issue 36: tracking, learning, SCN) accept its
interface: every input, output and parameter its class file declares, with the same
defaults. The names and defaults below are those of the original's current class files
(reference: IKAROS3-INTERFACES.md)."""
import pytest

import ikaros

INTERFACES = {
    "PyramidalLucasKanadeTracker": (
        ["IMAGE", "KEYPOINTS", "TEMPLATE_KEYPOINTS", "TEMPLATE_RANGES", "SEED_HOMOGRAPHY",
         "SEED_RESULT", "SEED_INLIERS"],
        ["TRANSFORM", "REFERENCE_POINTS", "CURRENT_POINTS", "RESULT"],
        {"image_width": "320", "image_height": "240", "levels": "3", "window_radius": "3",
         "iterations": "10", "max_residual": "0.08", "forward_backward_threshold": "1.5",
         "min_points": "6", "max_points": "512", "max_reseed_displacement": "20"}),
    "RobustTransformEstimator": (
        ["KEYPOINTS", "TEMPLATE_KEYPOINTS", "TEMPLATE_RANGES", "TEMPLATE_CORNERS",
         "CORRESPONDENCES"],
        ["HOMOGRAPHY", "INLIERS", "RESULT"],
        {"reprojection_threshold": "3", "min_inliers": "6", "min_inlier_ratio": "0",
         "min_mean_match_score": "0", "min_source_coverage": "0", "max_mean_error": "3",
         "image_width": "320", "image_height": "240", "min_area_fraction": "0.005",
         "max_area_fraction": "0.75", "ransac_iterations": "256", "max_matches": "512",
         "max_templates": "16"}),
    "ImageMatching": (
        ["LEFT", "RIGHT"],
        ["OUTPUT", "FOCUS", "TARGET", "PROFILE"],
        {"focus_size": "0.01", "search_size": "0.4"}),
    "FeaturePointBoxes": (
        ["POINTS"],
        ["BOXES"],
        {"image_width": "320", "image_height": "240", "box_size": "6", "max_points": "8192"}),
    "FeatureRegionFilter": (
        ["KEYPOINTS", "DESCRIPTORS", "RESTRICT"],
        ["FILTERED_KEYPOINTS", "FILTERED_DESCRIPTORS"],
        {"image_width": "320", "image_height": "240", "region": "0.5", "max_features": "512",
         "descriptor_size": "128"}),
    "TemplateFeatureBank": (
        ["KEYPOINTS", "DESCRIPTORS", "SCORES", "LEARN", "CLEAR"],
        ["TEMPLATE_KEYPOINTS", "TEMPLATE_DESCRIPTORS", "TEMPLATE_SCORES", "TEMPLATE_RANGES",
         "TEMPLATE_CORNERS"],
        {"image_width": "320", "image_height": "240", "learning_region": "0.5", "min_features":
         "6", "max_templates": "16", "max_stored_features": "8192"}),
    "TemplatePolygonTransform": (
        ["HOMOGRAPHY", "RESULT", "TEMPLATE_CORNERS", "KEYPOINTS", "INLIERS", "TRACKED_POINTS"],
        ["PATH", "LOCATION", "MATCHED_FEATURES"],
        {"image_width": "320", "image_height": "240", "min_area_fraction": "0.002",
         "max_area_fraction": "0.9", "max_features": "512"}),
    "TemplateTrackingController": (
        ["DETECTION_TRANSFORM", "DETECTION_RESULT", "TRACKING_TRANSFORM", "TRACKING_RESULT"],
        ["MATCH_ENABLE", "TRANSFORM", "RESULT", "STATUS"],
        {"detection_interval": "10", "tracking_fb_threshold": "1.5"}),
    "PointsToSalience": (
        ["POINTS", "WIDTHS"],
        ["OUTPUT"],
        {"size_x": "64", "size_y": "64", "standard_deviation": "0.2"}),
    "DeepNetwork": (
        ["INPUT", "EFFORT", "T_INPUT", "T_TARGET"],
        ["OUTPUT", "LOSS"],
        {"spec_filename": "network_spec.json", "weights_filename": "network_weights.dat",
         "load_weights": "yes", "save_weights": "no", "learning_rate": "0.001"}),
    "ConvolutionalVariationalAutoEncoder": (
        ["INPUT", "TOP_DOWN", "EFFORT"],
        ["OUTPUT", "LATENT_MEAN", "LATENT_LOG_VARIANCE", "LATENT_SAMPLE", "LOSS",
         "RECONSTRUCTION_LOSS", "KL_LOSS"],
        {"latent_mode": "dense", "latent_size": "8", "latent_maps": "4", "latent_kernel_size":
         "1", "feature_maps": "4", "kernel_size": "3", "padding": "valid", "learning_rate":
         "0.001", "optimizer": "adam", "adam_beta1": "0.9", "adam_beta2": "0.999",
         "adam_epsilon": "0.00000001", "beta": "1", "train": "yes", "train_interval": "1",
         "dense_train_interval": "1", "sample": "yes", "reconstruction_source": "sample",
         "output_activation": "linear"}),
    "FaceClassifier": (
        ["INPUT", "LEARN"],
        ["OUTPUT", "NOVELTY", "DISTANCE", "CLASSES", "COUNT", "VECTORS"],
        {"capacity": "16", "threshold": "0.6", "confirmation_count": "3", "k": "3",
         "vectors_per_class": "5"}),
    "SCN": (
        ["INPUT"],
        ["OUTPUT", "DIFF"],
        {"frequency": "0.00001111111111"}),
}


def same(declared, text):
    """Whether a declared default is the value of the original's default text."""
    if isinstance(declared, bool):
        return declared == (text == "yes")
    if isinstance(declared, (int, float)):
        return float(declared) == float(text)
    return str(declared) == text


@pytest.mark.parametrize("name", sorted(INTERFACES))
def test_ikaros3_interface(name):
    description = ikaros.classes()[name]
    inputs, outputs, parameters = INTERFACES[name]
    assert set(inputs) <= {i.name for i in description.inputs}
    assert set(outputs) <= {o.name for o in description.outputs}
    declared = {p.name: p for p in description.parameters}
    for parameter, default in parameters.items():
        spec = declared[parameter]
        value = spec.default if spec.default_v3 is None else spec.default_v3
        assert same(value, default), (name, parameter, value, default)
