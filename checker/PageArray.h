#pragma once
// A growable array of plain values in its own anonymous memory mapping, for the explorer's large
// per-state arrays (the state arena, the hash table, parent links). A std::vector copies every
// element when it grows and writes zeros into new elements; on a state space of millions that is
// most of the memory traffic, and every fresh page costs a fault. Here growth remaps the pages
// (mremap moves no data), fresh pages are zero because the kernel gives zero pages, and mappings of
// 2 MiB or more ask for transparent huge pages, one fault per 2 MiB instead of per 4 KiB.

#include <algorithm>
#include <cstddef>
#include <cstring>
#include <new>
#include <type_traits>
#include <utility>

#include <sys/mman.h>

namespace holon::checker {

template <class T>
class PageArray {
    static_assert(std::is_trivially_copyable_v<T> && std::is_trivially_destructible_v<T>,
                  "plain values only");

public:
    PageArray() = default;
    PageArray(const PageArray&) = delete;
    PageArray& operator=(const PageArray&) = delete;
    PageArray(PageArray&& o) noexcept { swap(o); }
    PageArray& operator=(PageArray&& o) noexcept {
        PageArray(std::move(o)).swap(*this);
        return *this;
    }
    ~PageArray() { release(); }

    std::size_t size() const { return size_; }
    bool empty() const { return size_ == 0; }
    T* data() { return data_; }
    const T* data() const { return data_; }
    T& operator[](std::size_t i) { return data_[i]; }
    const T& operator[](std::size_t i) const { return data_[i]; }
    T* begin() { return data_; }
    T* end() { return data_ + size_; }
    const T* begin() const { return data_; }
    const T* end() const { return data_ + size_; }

    /// New elements are zero, as std::vector<T>::resize gives for integers.
    void resize(std::size_t n) {
        if (n > size_) {
            reserve(n);
            // Pages beyond the high-water mark are still the kernel's zero pages; only elements
            // that were in use before a shrink need clearing.
            if (size_ < dirty_)
                std::memset(static_cast<void*>(data_ + size_), 0, (std::min(n, dirty_) - size_) * sizeof(T));
            if (n > dirty_) dirty_ = n;
        }
        size_ = n;
    }
    void push_back(const T& value) {
        resize(size_ + 1);
        data_[size_ - 1] = value;
    }
    /// Gives back the pages beyond size().
    void shrinkToFit() {
        const std::size_t want = roundUp(size_ * sizeof(T));
        if (want == 0) return release();
        if (want < mapped_) remap(want);
        dirty_ = std::min(dirty_, mapped_ / sizeof(T));
    }
    void swap(PageArray& o) noexcept {
        std::swap(data_, o.data_), std::swap(size_, o.size_), std::swap(dirty_, o.dirty_),
            std::swap(mapped_, o.mapped_);
    }

private:
    /// Room for n elements without remapping; at least doubles a small mapping.
    void reserve(std::size_t n) {
        const std::size_t want = roundUp(n * sizeof(T));
        if (want <= mapped_) return;
        remap(std::max(want, std::min(2 * mapped_, mapped_ + (std::size_t{1} << 30))));
    }
    static constexpr std::size_t kPage = 4096, kHuge = std::size_t{2} << 20;
    static std::size_t roundUp(std::size_t bytes) {
        const std::size_t unit = bytes >= kHuge ? kHuge : kPage;
        return (bytes + unit - 1) / unit * unit;
    }
    void remap(std::size_t bytes) {
        void* p = mapped_ == 0
                      ? mmap(nullptr, bytes, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0)
                      : mremap(data_, mapped_, bytes, MREMAP_MAYMOVE);
        if (p == MAP_FAILED) throw std::bad_alloc();
        if (bytes >= kHuge) madvise(p, bytes, MADV_HUGEPAGE);
        data_ = static_cast<T*>(p);
        mapped_ = bytes;
    }
    void release() {
        if (mapped_) munmap(data_, mapped_);
        data_ = nullptr, size_ = dirty_ = mapped_ = 0;
    }

    T* data_ = nullptr;
    std::size_t size_ = 0;
    std::size_t dirty_ = 0;   // elements [0, dirty_) may hold data; beyond, the pages are zero
    std::size_t mapped_ = 0;  // bytes
};

}  // namespace holon::checker
