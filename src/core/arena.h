// A bump allocator reset after every camera sample: BSDFs and other per-hit objects are
// placed here so the render loop never calls malloc. Objects must be trivially destructible
// or not need destruction.
#pragma once
#include <cstddef>
#include <cstdlib>
#include <memory>
#include <new>
#include <utility>
#include <vector>

namespace eyetrace {

class ScratchBuffer {
 public:
  explicit ScratchBuffer(size_t bytes = 64 * 1024) : size_(bytes), data_(new std::byte[bytes]) {}
  template <typename T, typename... Args>
  T* alloc(Args&&... args) {
    size_t align = alignof(T);
    offset_ = (offset_ + align - 1) & ~(align - 1);
    if (offset_ + sizeof(T) > size_) grow(sizeof(T) + align);
    T* p = new (data_.get() + offset_) T(std::forward<Args>(args)...);
    offset_ += sizeof(T);
    return p;
  }
  void reset() {
    offset_ = 0;
    retired_.clear();
  }

 private:
  void grow(size_t at_least) {
    retired_.push_back(std::move(data_));
    size_ = std::max(size_ * 2, at_least);
    data_.reset(new std::byte[size_]);
    offset_ = 0;
  }
  size_t size_;
  size_t offset_ = 0;
  std::unique_ptr<std::byte[]> data_;
  std::vector<std::unique_ptr<std::byte[]>> retired_;
};

}  // namespace eyetrace
