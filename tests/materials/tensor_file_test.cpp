// The RGL tensor-file reader: it reads the committed test file as tools/make_measured_bsdf
// described it, and rejects broken files with a TensorFileError saying what is wrong (bad
// magic, unknown version, truncation at any byte, sizes beyond the file, unknown types,
// duplicate fields), never a crash or a runaway allocation; random byte corruption of a valid
// file is either rejected or gives a BRDF whose values are finite.
#include <gtest/gtest.h>

#include <random>

#include "../support/temp_files.h"
#include "../support/tensor_file_writer.h"
#include "../support/unity_id.h"
#include "materials/measured_brdf.h"
#include "materials/measured_bxdf.h"

namespace eyetrace {
namespace {
namespace EYETRACE_UNITY_ID {

const std::string kFile = std::string(EYETRACE_SOURCE_DIR) + "/tests/data/measured/ggx-schlick.bsdf";

std::string valid_bytes() { return test::read_text(kFile); }

// The reader's message for `bytes` ("" when it accepts them).
std::string error_of(const std::string& bytes) {
  try {
    parse_tensor_file(bytes);
  } catch (const TensorFileError& e) {
    return e.what();
  }
  return "";
}

// Where the name of the field "ndf" starts in the field table (after its length, 3).
size_t ndf_entry(const std::string& bytes) { return bytes.find(std::string("\x03\0ndf", 5)) + 2; }

bool has(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

TEST(TensorFile, ReadsTheCommittedFileAsItsReadmeDescribesIt) {
  const TensorFile f = read_tensor_file(kFile);
  ASSERT_NE(f.find("spectra"), nullptr);
  EXPECT_EQ(f.find("spectra")->shape, (std::vector<uint64_t>{1, 13, 6, 24, 24}));
  EXPECT_EQ(f.find("vndf")->shape, (std::vector<uint64_t>{1, 13, 24, 24}));
  EXPECT_EQ(f.find("ndf")->shape, (std::vector<uint64_t>{4, 64}));
  const std::vector<float> theta = f.find("theta_i")->floats(), lambda = f.find("wavelengths")->floats();
  ASSERT_EQ(theta.size(), 13u);
  EXPECT_NEAR(theta.back(), 89.0 * kRadiansPerDegree, 1e-6);
  EXPECT_FLOAT_EQ(lambda.front(), 360.f);
  EXPECT_FLOAT_EQ(lambda.back(), 830.f);
  const std::vector<uint8_t>& d = f.find("description")->bytes;
  EXPECT_TRUE(has(std::string(d.begin(), d.end()), "GGX alpha 0.5"));
  // Written back (in another field order) and read again, every field is the same.
  const TensorFile again = parse_tensor_file(test::serialize_tensor_file(f));
  ASSERT_EQ(again.fields.size(), f.fields.size());
  for (const auto& [name, field] : f.fields) {
    EXPECT_EQ(again.find(name)->shape, field.shape) << name;
    EXPECT_EQ(again.find(name)->bytes, field.bytes) << name;
  }
}

TEST(TensorFile, RejectsABadMagicOrVersion) {
  std::string b = valid_bytes();
  b[0] = 'T';
  EXPECT_TRUE(has(error_of(b), "not a tensor file")) << error_of(b);
  b = valid_bytes();
  b[12] = 2;
  EXPECT_TRUE(has(error_of(b), "version 2.0")) << error_of(b);
  EXPECT_TRUE(has(error_of("hello"), "truncated")) << error_of("hello");
}

TEST(TensorFile, RejectsTruncationAtAnyByte) {
  const std::string b = valid_bytes();
  // Every length within the header and field table, then a spread through the data.
  std::vector<size_t> lengths;
  for (size_t n = 0; n < 700; ++n) lengths.push_back(n);
  for (size_t n = 700; n < b.size(); n += 997) lengths.push_back(n);
  lengths.push_back(b.size() - 1);
  for (size_t n : lengths) {
    const std::string e = error_of(b.substr(0, n));
    EXPECT_TRUE(has(e, "truncated")) << n << ": " << e;
  }
  EXPECT_EQ(error_of(b), "");
}

TEST(TensorFile, RejectsSizesBeyondTheFileWithoutAllocating) {
  TensorFile f = read_tensor_file(kFile);
  TensorField huge = f.fields["ndf"];
  huge.shape = {uint64_t(1) << 40, uint64_t(1) << 40};  // 2^80 elements: would overflow 64 bits
  f.fields["ndf"] = huge;
  // The serializer writes the small data; the header claims 2^80 elements.
  std::string e = error_of(test::serialize_tensor_file(f));
  EXPECT_TRUE(has(e, "truncated") && has(e, "\"ndf\"")) << e;
  // An offset past the end.
  std::string b = valid_bytes();
  const size_t at = ndf_entry(b) + 3 + 2 + 1;  // name, rank, type: then the offset
  const uint64_t far = uint64_t(1) << 62;
  std::memcpy(b.data() + at, &far, 8);
  e = error_of(b);
  EXPECT_TRUE(has(e, "truncated") && has(e, "\"ndf\"")) << e;
}

TEST(TensorFile, RejectsUnknownTypesAndDuplicateFields) {
  std::string b = valid_bytes();
  b[ndf_entry(b) + 3 + 2] = 12;  // after the name and the rank: type 12 does not exist
  EXPECT_TRUE(has(error_of(b), "unknown element type 12")) << error_of(b);
  // Repeat the first entry of the field table (description: name length 11, rank 1, one size).
  std::string two = test::serialize_tensor_file(read_tensor_file(kFile));
  uint32_t n = 0;
  std::memcpy(&n, two.data() + 14, 4);
  const size_t entry = 2 + 11 + 2 + 1 + 8 + 8;
  ASSERT_EQ(two.substr(20, 11), "description");
  two.insert(18, two.substr(18, entry));
  ++n;
  std::memcpy(two.data() + 14, &n, 4);
  EXPECT_TRUE(has(error_of(two), "field \"description\" appears twice")) << error_of(two);
}

// Random corruption (1 to 8 bytes changed, 3000 times): the reader and the BRDF checks either
// refuse the file with a TensorFileError, or the BRDF they accept evaluates and samples to
// finite values (NaN-free).
TEST(TensorFile, RandomCorruptionIsRejectedOrHarmless) {
  const std::string good = valid_bytes();
  std::mt19937 rng(42);
  int rejected = 0, accepted = 0;
  const SampledWavelengths lambda = SampledWavelengths::sample_uniform(0.5f);
  for (int trial = 0; trial < 3000; ++trial) {
    std::string b = good;
    const int n = 1 + int(rng() % 8);
    for (int k = 0; k < n; ++k) {
      // Half the changes hit the header and field table, where the structure is.
      const size_t at = (k % 2 == 0) ? rng() % 700 : rng() % b.size();
      b[at] = char(rng() & 0xff);
    }
    std::shared_ptr<const MeasuredBRDF> brdf;
    try {
      brdf = make_measured_brdf(parse_tensor_file(b));
    } catch (const TensorFileError&) {
      ++rejected;
      continue;
    }
    ++accepted;
    const MeasuredBxDF bxdf(brdf.get(), lambda);
    const Vec3 wo = glm::normalize(Vec3(0.3f, 0.1f, 0.9f)), wi = glm::normalize(Vec3(-0.5f, 0.2f, 0.6f));
    ASSERT_TRUE(is_finite(bxdf.f(wo, wi))) << trial;
    ASSERT_TRUE(std::isfinite(bxdf.pdf(wo, wi))) << trial;
    if (auto s = bxdf.sample_f(wo, 0.5f, Vec2(0.3f, 0.7f))) ASSERT_TRUE(is_finite(s->f) && std::isfinite(s->pdf));
  }
  EXPECT_GT(rejected, 100);
  EXPECT_GT(accepted, 100);  // most data bytes change values, not structure
  RecordProperty("rejected", rejected);
  RecordProperty("accepted", accepted);
}

}  // namespace EYETRACE_UNITY_ID
}  // namespace
}  // namespace eyetrace
