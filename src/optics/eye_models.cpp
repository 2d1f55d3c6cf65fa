// Eye presets. The relaxed prescriptions come from the embedded data files; what varies with
// the options (accommodation, pupil, refractive error, retina, wavelength) is applied here, in
// that order, each step a small function of a Prescription.
#include "optics/eye_models.h"

#include <algorithm>
#include <cmath>

#include <fmt/format.h>

#include "optics/navarro.h"
#include "optics/optics_error.h"
#include "optics/paraxial.h"
#include "optics/prescription_io.h"

namespace eyetrace::optics {

namespace {

[[noreturn]] void bad_option(const char* option, const std::string& message) {
    throw OpticsError(fmt::format("eye option '{}': {}", option, message));
}

std::string join(const std::vector<std::string>& names) {
    std::string out;
    for (const std::string& n : names) out += (out.empty() ? "" : ", ") + n;
    return out;
}

// Linear interpolation of two states of one eye with the same surfaces: curvature, conic,
// thickness and indices (media by name). f = 0 gives a, f = 1 gives b.
Prescription interpolate(const Prescription& a, const Prescription& b, double f) {
    Prescription p = a;
    auto lerp = [f](double x, double y) { return x + f * (y - x); };
    for (size_t i = 0; i < p.surfaces.size(); ++i) {
        Surface& s = p.surfaces[i];
        const Surface& t = b.surfaces[i];
        s.profile = SurfaceProfile::from_curvature(
            lerp(a.surfaces[i].profile.is_flat() ? 0.0 : a.surfaces[i].profile.curvature,
                 t.profile.is_flat() ? 0.0 : t.profile.curvature),
            lerp(s.profile.conic, t.profile.conic));
        s.thickness_mm = lerp(s.thickness_mm, t.thickness_mm);
        s.index_after = lerp(s.index_after, t.index_after);
    }
    for (Medium& m : p.media)
        if (const Medium* mb = b.find_medium(m.name)) m.index = lerp(m.index, mb->index);
    return p;
}

// --- Gullstrand exact eye No. 1 -----------------------------------------------------------
// Atchison & Smith's continuous version (eye-models.md section 1): every curvature and
// thickness moves linearly from the relaxed to the accommodated state by x / 10.87013 with
// x = 1.052 A - 0.00531 A^2 + 0.000048564 A^3; the eye then focuses at -A within 0.002 D.
constexpr double kGullstrandMaxA = 10.87013;

void clip_gullstrand_nucleus(Prescription& p) {
    // The nucleus ends where its two faces meet; its semi-diameter is that height.
    for (size_t i = 0; i + 1 < p.surfaces.size(); ++i) {
        if (p.surfaces[i].name != "lens nucleus anterior") continue;
        Surface& front = p.surfaces[i];
        Surface& back = p.surfaces[i + 1];
        const std::vector<double> z = p.vertex_z_mm();
        const double h_max = std::min({front.profile.max_height(), back.profile.max_height(), 3.75});
        const double edge = meeting_height(front.profile, z[i], back.profile, z[i + 1], h_max);
        front.semi_diameter_mm = back.semi_diameter_mm = edge;
    }
}

Prescription gullstrand(double A) {
    Prescription p = load_embedded_prescription("gullstrand.json");
    if (A == 0.0) {
        clip_gullstrand_nucleus(p);
        return p;
    }
    const double x = 1.052 * A - 0.00531 * A * A + 0.000048564 * A * A * A;
    p = interpolate(p, load_embedded_prescription("gullstrand-accommodated.json"), x / kGullstrandMaxA);
    clip_gullstrand_nucleus(p);
    p.notes.push_back(fmt::format("accommodation {} D: Atchison & Smith continuous version of the "
                                  "Gullstrand eye (interpolation fraction {:.5f})", A, x / kGullstrandMaxA));
    return p;
}

// --- Le Grand ------------------------------------------------------------------------------
// Le Grand publishes a relaxed and one accommodated state (7.053 D). In between, every
// curvature, thickness and index moves linearly by one fraction f, and f is solved so the eye
// produces exactly the requested accommodation (the same idea as Gullstrand's continuous
// version, whose cubic is such a fit). Monotonic in f, so bisection is safe.
double legrand_max_accommodation() {
    static const double max_a =
        refraction_diopters(load_embedded_prescription("legrand.json")) -
        refraction_diopters(load_embedded_prescription("legrand-accommodated.json"));
    return max_a;
}

Prescription legrand(double A) {
    Prescription relaxed = load_embedded_prescription("legrand.json");
    if (A == 0.0) return relaxed;
    const Prescription accommodated = load_embedded_prescription("legrand-accommodated.json");
    const double target = refraction_diopters(relaxed) - A;
    double lo = 0.0, hi = 1.0;
    for (int it = 0; it < 60; ++it) {
        const double mid = 0.5 * (lo + hi);
        (refraction_diopters(interpolate(relaxed, accommodated, mid)) > target ? lo : hi) = mid;
    }
    const double f = 0.5 * (lo + hi);
    Prescription p = interpolate(relaxed, accommodated, f);
    p.notes.push_back(fmt::format("accommodation {} D: parameters interpolated linearly between Le "
                                  "Grand's relaxed and accommodated eyes (fraction {:.5f}, solved "
                                  "for the produced accommodation)", A, f));
    return p;
}

// --- Arizona --------------------------------------------------------------------------------
// Published formulas in the accommodation A (eye-models.md section 7). Beyond about 8.9 D the
// anterior lens becomes an oblate ellipsoid too small for the 3.75 mm lens rim, so the preset
// stops at 8 D.
constexpr double kArizonaMaxA = 8.0;

Prescription arizona(double A) {
    Prescription p = load_embedded_prescription("arizona.json");
    if (A == 0.0) return p;
    for (Surface& s : p.surfaces) {
        if (s.name == "cornea posterior") s.thickness_mm = 2.97 - 0.04 * A;
        if (s.name == "lens anterior") {
            s.profile = SurfaceProfile::from_radius(12.0 - 0.4 * A, -7.518749 + 1.285720 * A);
            s.thickness_mm = 3.767 + 0.04 * A;
        }
        if (s.name == "lens posterior")
            s.profile = SurfaceProfile::from_radius(-5.224557 + 0.2 * A, -1.353971 - 0.431762 * A);
    }
    for (Medium& m : p.media)
        if (m.name == "lens") m.index = 1.42 + 0.00256 * A - 0.00022 * A * A;
    for (Surface& s : p.surfaces)
        if (s.medium == "lens") s.index_after = p.find_medium("lens")->index;
    return p;
}

Prescription relaxed_or_accommodated(const std::string& model, const std::string& variant, double A) {
    if (model == "gullstrand") return gullstrand(A);
    if (model == "legrand") return legrand(A);
    if (model == "arizona") return arizona(A);
    if (model == "kooijman") return load_embedded_prescription("kooijman.json");
    if (model == "escudero-sanz")
        return navarro_accommodate(load_embedded_prescription("escudero-sanz.json"), A,
                                   NavarroLensIndexLaw::Navarro1985);
    if (variant == "wu2011")
        return navarro_accommodate(load_embedded_prescription("navarro-wu2011.json"), A,
                                   NavarroLensIndexLaw::Wu2011Printed);
    return navarro_accommodate(load_embedded_prescription("navarro.json"), A,
                               NavarroLensIndexLaw::Navarro1985);
}

void check_finite(const char* option, double value) {
    if (!std::isfinite(value)) bad_option(option, fmt::format("{} is not a finite number", value));
}

}  // namespace

std::vector<std::string> eye_model_names() {
    return {"arizona", "escudero-sanz", "gullstrand", "kooijman", "legrand", "navarro"};
}

std::vector<std::string> eye_model_variants(const std::string& model) {
    const std::vector<std::string> names = eye_model_names();
    if (std::find(names.begin(), names.end(), model) == names.end())
        bad_option("model", fmt::format("unknown eye model '{}'; valid models: {}", model, join(names)));
    if (model == "navarro") return {"", "wu2011"};
    return {""};
}

double max_accommodation_diopters(const std::string& model, const std::string& variant) {
    const std::vector<std::string> variants = eye_model_variants(model);
    if (std::find(variants.begin(), variants.end(), variant) == variants.end())
        bad_option("variant", fmt::format("model '{}' has no variant '{}'", model, variant));
    if (model == "gullstrand") return kGullstrandMaxA;
    if (model == "legrand") return legrand_max_accommodation();
    if (model == "kooijman") return 0.0;
    if (model == "arizona") return kArizonaMaxA;
    return kNavarroMaxD;  // navarro (both variants), escudero-sanz
}

Prescription make_eye(const EyeOptions& o) {
    const std::vector<std::string> variants = eye_model_variants(o.model);
    if (std::find(variants.begin(), variants.end(), o.variant) == variants.end()) {
        std::vector<std::string> shown;
        for (const std::string& v : variants) shown.push_back(v.empty() ? "\"\" (default)" : v);
        bad_option("variant", fmt::format("model '{}' has no variant '{}'; valid variants: {}",
                                          o.model, o.variant, join(shown)));
    }
    check_finite("accommodation", o.accommodation_D);
    check_finite("pupildiameter", o.pupil_diameter_mm);
    check_finite("refractiveerror", o.refractive_error_D);
    check_finite("wavelength", o.wavelength_nm);
    if (o.retina_radius_mm) check_finite("retinaradius", *o.retina_radius_mm);

    if (!(o.pupil_diameter_mm > 0.0 && o.pupil_diameter_mm <= 10.0))
        bad_option("pupildiameter", fmt::format("{} mm is outside (0, 10] mm", o.pupil_diameter_mm));
    const double max_a = max_accommodation_diopters(o.model, o.variant);
    if (o.accommodation_D < 0.0 || o.accommodation_D > max_a)
        bad_option("accommodation",
                   max_a == 0.0
                       ? fmt::format("model '{}' has no accommodation model (only 0 D); got {} D",
                                     o.model, o.accommodation_D)
                       : fmt::format("{} D is outside the range of model '{}' [0, {:.5g}] D",
                                     o.accommodation_D, o.model, max_a));
    if (std::abs(o.refractive_error_D) > 30.0)
        bad_option("refractiveerror", fmt::format("{} D is outside [-30, 30] D", o.refractive_error_D));
    if (o.retina_radius_mm && *o.retina_radius_mm > 0.0)
        bad_option("retinaradius", fmt::format("{} mm must be negative (centre of curvature in "
                                               "front of the retina) or 0 for flat", *o.retina_radius_mm));
    if (o.wavelength_nm != 0.0 && (o.wavelength_nm < kMinWavelengthNm || o.wavelength_nm > kMaxWavelengthNm))
        bad_option("wavelength", fmt::format("{} nm is outside [{}, {}] nm (0 = the model's reference)",
                                             o.wavelength_nm, kMinWavelengthNm, kMaxWavelengthNm));

    Prescription p = relaxed_or_accommodated(o.model, o.variant, o.accommodation_D);
    p.variant = o.variant;
    const int retina = p.image_index();
    const int vitreous = retina - 1;

    if (o.refractive_error_D != 0.0) {
        // Axial length from the relaxed eye; accommodation keeps the axial length (all models).
        Prescription relaxed = relaxed_or_accommodated(o.model, o.variant, 0.0);
        const double old_length = relaxed.axial_length_mm();
        double new_length;
        try {
            new_length = image_position_for_refraction(relaxed, o.refractive_error_D);
        } catch (const OpticsError& e) {
            bad_option("refractiveerror", e.what());
        }
        p.surfaces[vitreous].thickness_mm += new_length - old_length;
        p.notes.push_back(fmt::format("refractive error {} D: axial length {:.4f} mm instead of {:.4f} mm",
                                      o.refractive_error_D, new_length, old_length));
    }
    if (o.retina_radius_mm)
        p.surfaces[retina].profile = SurfaceProfile::from_radius(*o.retina_radius_mm, 0.0);
    set_stop_diameter(p, o.pupil_diameter_mm);
    if (o.wavelength_nm != 0.0 && o.wavelength_nm != p.reference_wavelength_nm) {
        p = at_wavelength(p, o.wavelength_nm);
        for (const Medium& m : p.media)
            if (m.dispersion.law == DispersionLaw::None) {
                p.notes.push_back(fmt::format("medium '{}' has no dispersion data: its index is "
                                              "the same at every wavelength", m.name));
            }
    }
    try {
        validate(p);
    } catch (const OpticsError& e) {
        throw OpticsError(fmt::format("eye model '{}' with these options is not a valid system: {}",
                                      o.model, e.what()));
    }
    return p;
}

}  // namespace eyetrace::optics
