// The measured-BRDF loader's checks (measured_brdf.h): each required field missing, of the
// wrong type, of a shape that does not match the others, or with values the interpolants
// cannot use (NaN, a zero projected area, an empty warp slice, decreasing nodes, a 1-wide
// grid) is a TensorFileError naming the field; an RGB-only file is refused as pbrt-v4 refuses
// it; the cache reads a file once while it is in use.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>

#include "../support/temp_files.h"
#include "../support/tensor_file_writer.h"
#include "../support/unity_id.h"
#include "materials/measured_brdf.h"

namespace eyetrace {
namespace {
namespace EYETRACE_UNITY_ID {

const std::string kFile = std::string(EYETRACE_SOURCE_DIR) + "/tests/data/measured/ggx-schlick.bsdf";

// The loader's message after `edit` changed the committed file ("" when it is accepted).
std::string error_after(const std::function<void(TensorFile&)>& edit) {
  TensorFile f = read_tensor_file(kFile);
  edit(f);
  try {
    make_measured_brdf(f);
  } catch (const TensorFileError& e) {
    return e.what();
  }
  return "";
}

bool has(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

// Sets element i of a float32 field.
void set_float(TensorField& f, size_t i, float v) { std::memcpy(f.bytes.data() + 4 * i, &v, 4); }

TEST(MeasuredBRDF, TheCommittedFileIsAccepted) {
  EXPECT_EQ(error_after([](TensorFile&) {}), "");
}

TEST(MeasuredBRDF, EachMissingFieldIsNamed) {
  for (const char* name :
       {"description", "jacobian", "theta_i", "phi_i", "wavelengths", "ndf", "sigma", "vndf", "luminance", "spectra"}) {
    const std::string e = error_after([&](TensorFile& f) { f.fields.erase(name); });
    EXPECT_TRUE(has(e, std::string("no field \"") + name + "\"")) << name << ": " << e;
  }
}

TEST(MeasuredBRDF, AnRgbOnlyFileIsRefusedAsByPbrtV4) {
  const std::string e = error_after([](TensorFile& f) {
    f.fields["rgb"] = f.fields["spectra"];
    f.fields.erase("spectra");
  });
  EXPECT_TRUE(has(e, "\"rgb\"") && has(e, "pbrt-v4")) << e;
}

TEST(MeasuredBRDF, WrongTypesAndShapesAreNamed) {
  std::string e = error_after([](TensorFile& f) { f.fields["ndf"].dtype = TensorField::UInt32; });
  EXPECT_TRUE(has(e, "\"ndf\" is uint32 [4, 64]; expected float32 of rank 2")) << e;
  e = error_after([](TensorFile& f) { f.fields["vndf"].shape = {13, 24, 24}; });
  EXPECT_TRUE(has(e, "\"vndf\"") && has(e, "rank 4")) << e;
  // Spectra for 5 wavelengths while 6 are listed.
  e = error_after([](TensorFile& f) { f.fields["wavelengths"] = test::float_field({5}, {360, 400, 500, 600, 700}); });
  EXPECT_TRUE(has(e, "\"spectra\"") && has(e, "dimension 2; expected 5 (the wavelengths)")) << e;
  // vndf for 12 theta_i nodes while 13 are listed.
  e = error_after([](TensorFile& f) {
    TensorField& v = f.fields["vndf"];
    v.shape[1] = 12;
    v.bytes.resize(v.bytes.size() / 13 * 12);
  });
  EXPECT_TRUE(has(e, "\"vndf\"") && has(e, "expected 13 (the theta_i nodes)")) << e;
  // A luminance grid that is not the spectra's.
  e = error_after([](TensorFile& f) {
    TensorField& l = f.fields["luminance"];
    l.shape = {1, 13, 24, 12};
    l.bytes.resize(l.bytes.size() / 2);
  });
  EXPECT_TRUE(has(e, "\"luminance\"") && has(e, "spectra's grid")) << e;
  e = error_after([](TensorFile& f) { f.fields["jacobian"].shape = {2}; });
  EXPECT_TRUE(has(e, "\"jacobian\"")) << e;
  e = error_after([](TensorFile& f) { f.fields["ndf"] = test::float_field({4, 1}, {1, 1, 1, 1}); });
  EXPECT_TRUE(has(e, "\"ndf\"") && has(e, "at least 2 x 2")) << e;
}

TEST(MeasuredBRDF, ValuesTheInterpolantsCannotUseAreNamed) {
  std::string e = error_after([](TensorFile& f) { set_float(f.fields["spectra"], 1000, std::nanf("")); });
  EXPECT_TRUE(has(e, "\"spectra\"") && has(e, "element 1000") && has(e, "finite")) << e;
  e = error_after([](TensorFile& f) { set_float(f.fields["sigma"], 7, 0.f); });
  EXPECT_TRUE(has(e, "\"sigma\"") && has(e, "> 0")) << e;
  e = error_after([](TensorFile& f) { set_float(f.fields["vndf"], 3, -1.f); });
  EXPECT_TRUE(has(e, "\"vndf\"") && has(e, ">= 0")) << e;
  e = error_after([](TensorFile& f) {
    TensorField& l = f.fields["luminance"];
    for (size_t i = 0; i < 24 * 24; ++i) set_float(l, 2 * 24 * 24 + i, 0.f);  // slice 2: no mass
  });
  EXPECT_TRUE(has(e, "\"luminance\" is zero everywhere in slice 2")) << e;
  e = error_after([](TensorFile& f) { set_float(f.fields["theta_i"], 5, 0.1f); });
  EXPECT_TRUE(has(e, "\"theta_i\" is not increasing")) << e;
}

// pbrt-v4 reads anisotropic files only when phi_i covers the whole circle.
TEST(MeasuredBRDF, AnisotropicFilesMustCoverTheCircle) {
  auto aniso = [](float phi_span) {
    return [phi_span](TensorFile& f) {
      f.fields["phi_i"] = test::float_field({3}, {-phi_span / 2, 0.f, phi_span / 2});
      for (const char* name : {"vndf", "luminance", "spectra"}) {
        TensorField& t = f.fields[name];
        const std::vector<uint8_t> one = t.bytes;
        t.shape[0] = 3;
        t.bytes.clear();
        for (int k = 0; k < 3; ++k) t.bytes.insert(t.bytes.end(), one.begin(), one.end());
      }
    };
  };
  EXPECT_EQ(error_after(aniso(float(kTwoPiDouble))), "");
  const std::string e = error_after(aniso(float(kPiDouble / 2)));
  EXPECT_TRUE(has(e, "phi_i spans 1/4 of the circle")) << e;
}

TEST(MeasuredBRDF, AFileIsReadOnceWhileInUse) {
  test::TempDir dir("measured-cache");
  const std::string path = dir.file("copy.bsdf");
  std::filesystem::copy_file(kFile, path);
  std::shared_ptr<const MeasuredBRDF> a = load_measured_brdf(path);
  // Removing the file shows the second load does not read it.
  std::filesystem::remove(path);
  std::shared_ptr<const MeasuredBRDF> b = load_measured_brdf(path);
  EXPECT_EQ(a.get(), b.get());
  a.reset();
  b.reset();
  // Once no material holds it, it is gone: the path is read again (and now missing).
  EXPECT_THROW(load_measured_brdf(path), TensorFileError);
}

}  // namespace EYETRACE_UNITY_ID
}  // namespace
}  // namespace eyetrace
