// psf_image (optics/psf_image.h) restates compute_psf's pupil-function FFT without its Strehl
// ratio and encircled energy: it must give compute_psf's samples, sample spacing and phase step.
#include <gtest/gtest.h>

#include "../support/unity_id.h"
#include "optics/eye_models.h"
#include "optics/psf.h"
#include "optics/psf_image.h"
#include "optics/wavefront.h"

namespace eyetrace::optics {
namespace {
namespace EYETRACE_UNITY_ID {

TEST(PsfImage, EqualsComputePsf) {
  EyeOptions eo;
  eo.model = "navarro";
  eo.pupil_diameter_mm = 3.0;
  const Prescription p = make_eye(eo);
  for (double field : {0.0, 20.0}) {
    WavefrontOptions o;
    o.field_deg = field;
    o.wavelength_nm = 500.0;
    o.clip_at_stop = true;
    o.grid = 48;
    const WavefrontResult w = trace_wavefront(p, o);
    const Psf psf = compute_psf(w, retinal_scale(p, field, o.object_distance_m, 500.0));
    const PsfImage image = psf_image(w);
    ASSERT_EQ(image.fft_size, psf.fft_size);
    EXPECT_DOUBLE_EQ(image.sample_x_rad, psf.sample_x_rad);
    EXPECT_DOUBLE_EQ(image.sample_y_rad, psf.sample_y_rad);
    EXPECT_DOUBLE_EQ(image.max_phase_step_rad, psf.max_phase_step_rad);
    ASSERT_EQ(image.intensity.size(), psf.intensity.size());
    for (size_t i = 0; i < psf.intensity.size(); ++i) ASSERT_NEAR(image.intensity[i], psf.intensity[i], 1e-12) << i;
  }
}

TEST(PsfImage, RejectsAnEmptyWavefront) { EXPECT_ANY_THROW(psf_image(WavefrontResult{})); }

}  // namespace EYETRACE_UNITY_ID
}  // namespace
}  // namespace eyetrace::optics
