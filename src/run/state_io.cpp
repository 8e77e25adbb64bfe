#include "run/state_io.hpp"

#include "core/error.hpp"
#include "run/checkpoint_file.hpp"

#include <cstdint>
#include <cstring>

namespace granseg {

// Each value: the name's length (2 bytes) and the name, the element size (4 bytes), the element
// count (8 bytes), then the elements' bytes as they are in memory.

StateIO::StateIO(std::string bytes, std::string source, const BlobStore* blobs)
    : restoring_(true), stored_(blobs), bytes_(std::move(bytes)), source_(std::move(source)) {}

StateIO& StateIO::blob(const char* name, std::string& text) {
    if (!restoring_ && !blobs_) return (*this)(name, text);
    if (restoring_ && !stored_) return (*this)(name, text);
    std::string key;
    if (!restoring_) {
        // The key: the contents' hash and length, and a suffix in the (unlikely) case two texts share them.
        key = hash_text(text) + ":" + std::to_string(text.size());
        for (auto it = blobs_->find(key); it != blobs_->end() && it->second != text; it = blobs_->find(key)) key += "+";
        blobs_->emplace(key, text);
    }
    (*this)((std::string(name) + ".key").c_str(), key);  // another name than a text saved as a member
    if (restoring_) {
        const auto it = stored_->find(key);
        if (it == stored_->end()) fail("the state names a file \"" + key + "\" that the checkpoint does not hold");
        text = it->second;
    }
    return *this;
}

void StateIO::fail(const std::string& what) const {
    throw InputError(source_ + ": " + what + " (allowed: a checkpoint of this scene written by this build of granseg)");
}

std::size_t StateIO::count(const char* name, std::size_t element) {
    const auto take = [&](void* out, std::size_t n) {
        if (bytes_.size() - at_ < n) fail(std::string("the state ends before \"") + name + "\"");
        std::memcpy(out, bytes_.data() + at_, n);
        at_ += n;
    };
    std::uint16_t length = 0;
    take(&length, sizeof length);
    std::string saved(length, '\0');
    take(saved.data(), length);
    std::uint32_t size = 0;
    std::uint64_t n = 0;
    take(&size, sizeof size);
    take(&n, sizeof n);
    if (saved != name) fail("the state holds \"" + saved + "\" where this program reads \"" + name + "\"");
    if (size != element)
        fail(std::string("\"") + name + "\" has elements of " + std::to_string(size) + " bytes, this program's of " +
             std::to_string(element));
    if (n > (bytes_.size() - at_) / (element ? element : 1)) fail(std::string("the state ends inside \"") + name + "\"");
    counted_ = true;
    return static_cast<std::size_t>(n);
}

void StateIO::transfer(const char* name, void* data, std::size_t element, std::size_t n) {
    const std::size_t bytes = element * n;
    if (!restoring_) {
        const auto length = static_cast<std::uint16_t>(std::strlen(name));
        const auto size = static_cast<std::uint32_t>(element);
        const auto count64 = static_cast<std::uint64_t>(n);
        bytes_.append(reinterpret_cast<const char*>(&length), sizeof length).append(name, length);
        bytes_.append(reinterpret_cast<const char*>(&size), sizeof size);
        bytes_.append(reinterpret_cast<const char*>(&count64), sizeof count64);
        bytes_.append(static_cast<const char*>(data), bytes);
        return;
    }
    if (!counted_ && count(name, element) != n) fail(std::string("\"") + name + "\" does not hold one value");
    counted_ = false;
    if (bytes) std::memcpy(data, bytes_.data() + at_, bytes);
    at_ += bytes;
}

void StateIO::expect_end() const {
    if (restoring_ && at_ != bytes_.size())
        fail(std::to_string(bytes_.size() - at_) + " bytes of the state were not read (saved by another program?)");
}

}  // namespace granseg
