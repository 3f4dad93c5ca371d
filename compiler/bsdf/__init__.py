"""cnlmc.bsdf — the numpy reference BSDF library (ground truth for every backend).

Local shading frame: normal +z, tangent +x; ``wo`` towards the viewer, ``wi`` towards
the light, unit vectors of shape (..., 3). Functions return BRDF values f (not
multiplied by cos θi); RGB results have shape (..., 3). See docs/bsdf.md.
"""

from .alpha import ALPHA_MIRROR, alpha_from_roughness, alpha_isotropic, anisotropy_stretch
from .diffuse import lambert, oren_nayar
from .evaluate import albedo, coat_alpha, conductor_fresnel, evaluate, material_alpha
from .fresnel import (
    f0_conductor,
    f0_from_ior,
    f82_from_tint,
    fresnel_average,
    fresnel_conductor,
    fresnel_dielectric,
    fresnel_f82,
    fresnel_f82_tint,
    fresnel_schlick,
    fresnel_schlick_average,
    ior_from_f0,
)
from .geometry import COS_EPS, dir_from_mu, rotate_tangent, spherical_dir
from .integrate import albedo_cosine, albedo_mis
from .layered import coated, diffuse_reflectance, fresnel_diffuse_reflectance, internal_reflectance, refract_into_coat
from .microfacet import (
    ggx_d,
    ggx_d_common_form,
    ggx_d_isotropic,
    ggx_visibility,
    microfacet_reflection,
    mirror_reflectance,
    sample_ggx_vndf,
    smith_g1,
    smith_g2,
    smith_g2_separable,
    smith_lambda,
)
from .multiscatter import albedo_lookup, average_albedo, fresnel_multiscatter, ggx_albedo, multiscatter_lobe
from .transmission import (
    dielectric_reflection,
    evaluate_bsdf,
    evaluate_transmission,
    generalized_half_vector,
    microfacet_transmission,
    mirror_transmittance,
    transmission_g2,
)
from .ward import ward, ward_1992, ward_duer, ward_gmd

__all__ = [
    "ALPHA_MIRROR",
    "COS_EPS",
    "alpha_from_roughness",
    "alpha_isotropic",
    "anisotropy_stretch",
    "lambert",
    "oren_nayar",
    "albedo",
    "coat_alpha",
    "conductor_fresnel",
    "evaluate",
    "material_alpha",
    "f0_conductor",
    "f0_from_ior",
    "f82_from_tint",
    "fresnel_average",
    "fresnel_conductor",
    "fresnel_dielectric",
    "fresnel_f82",
    "fresnel_f82_tint",
    "fresnel_schlick",
    "fresnel_schlick_average",
    "ior_from_f0",
    "dir_from_mu",
    "rotate_tangent",
    "spherical_dir",
    "albedo_cosine",
    "albedo_mis",
    "coated",
    "diffuse_reflectance",
    "fresnel_diffuse_reflectance",
    "internal_reflectance",
    "refract_into_coat",
    "ggx_d",
    "ggx_d_common_form",
    "ggx_d_isotropic",
    "ggx_visibility",
    "microfacet_reflection",
    "mirror_reflectance",
    "sample_ggx_vndf",
    "smith_g1",
    "smith_g2",
    "smith_g2_separable",
    "smith_lambda",
    "albedo_lookup",
    "average_albedo",
    "fresnel_multiscatter",
    "ggx_albedo",
    "multiscatter_lobe",
    "dielectric_reflection",
    "evaluate_bsdf",
    "evaluate_transmission",
    "generalized_half_vector",
    "microfacet_transmission",
    "mirror_transmittance",
    "transmission_g2",
    "ward",
    "ward_1992",
    "ward_duer",
    "ward_gmd",
]
