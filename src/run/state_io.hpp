// Saving and restoring the state of a run, for checkpoints (run/checkpoint_file.hpp,
// docs/checkpoints.md).
//
//   solves      nothing: turns the members of the classes of a run into bytes and back
//   inputs      each class's list of its members (below)
//   outputs     the bytes of a state; on restoring, the members set to the saved values
//   invariants  a restored value equals the saved one bit for bit (doubles are copied as bytes);
//               a state is read back in the order it was written, each value under its name and
//               with its size, so a list that changed cannot be misread silently
//
// A class that carries state from one step to the next lists its members once, in one function
// next to their declaration, for both directions:
//
//     void checkpoint(StateIO& io) { io("t", t_)("steps", steps_)("phi", phi_)("solver", solver_); }
//
// Saving appends every value; restoring reads each back into the member. A member is a number,
// an enum, a bool, a contiguous container of numbers (std::vector, std::string, Eigen vectors),
// a std::array or a std::vector of members, or a class with its own checkpoint(StateIO&) (it
// lists its members in turn). A member added to a class that the next step reads goes into its list as well: the
// kill-and-resume checks (verify_resume, tests/run/checkpoint.cpp) compare a resumed run with an
// uninterrupted one bit for bit and catch one forgotten.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <map>
#include <string>
#include <string_view>
#include <type_traits>
#include <utility>
#include <vector>

namespace granseg {

class StateIO;

namespace state_io_detail {
template <class T, class = void>
struct has_checkpoint : std::false_type {};
template <class T>
struct has_checkpoint<T, std::void_t<decltype(std::declval<T&>().checkpoint(std::declval<StateIO&>()))>> : std::true_type {};
template <class T, class = void>
struct is_contiguous : std::false_type {};
template <class T>
struct is_contiguous<T, std::void_t<decltype(std::declval<T&>().data()), decltype(std::declval<T&>().size()),
                                    decltype(std::declval<T&>().resize(std::size_t{}))>>
    : std::is_trivially_copyable<std::remove_pointer_t<decltype(std::declval<T&>().data())>> {};
template <class T>
struct is_array : std::false_type {};
template <class T, std::size_t N>
struct is_array<std::array<T, N>> : std::true_type {};
template <class T>
struct is_vector : std::false_type {};
template <class T, class A>
struct is_vector<std::vector<T, A>> : std::true_type {};
}  // namespace state_io_detail

/// Large texts that several states share (the output files a run has made: the state before the
/// last step and the final one hold the same), each kept once, by a key of its contents.
using BlobStore = std::map<std::string, std::string>;

class StateIO {
public:
    /// Saving: the values go into bytes(); blobs (below) into `blobs` if given.
    explicit StateIO(BlobStore* blobs = nullptr) : blobs_(blobs) {}
    /// Restoring from `bytes`; `source` names them in messages (the checkpoint file); blobs from
    /// `blobs` if the state was saved with a store.
    StateIO(std::string bytes, std::string source, const BlobStore* blobs = nullptr);

    bool restoring() const { return restoring_; }

    /// Saves or restores one member under `name`.
    template <class T>
    StateIO& operator()(const char* name, T& value) {
        using namespace state_io_detail;
        if constexpr (has_checkpoint<T>::value) {
            value.checkpoint(*this);
        } else if constexpr (is_array<T>::value) {
            for (std::size_t i = 0; i < value.size(); ++i)
                (*this)((std::string(name) + "." + std::to_string(i)).c_str(), value[i]);
        } else if constexpr (is_contiguous<T>::value) {
            using Element = std::remove_pointer_t<decltype(value.data())>;
            if (restoring_) value.resize(count(name, sizeof(Element)));
            transfer(name, value.data(), sizeof(Element), static_cast<std::size_t>(value.size()));
        } else if constexpr (is_vector<T>::value) {  // of strings, of classes: the count, then each
            std::uint64_t n = value.size();
            (*this)((std::string(name) + ".size").c_str(), n);
            if (restoring_) value.resize(static_cast<std::size_t>(n));
            for (auto& element : value) (*this)(name, element);
        } else {
            static_assert(std::is_arithmetic_v<T> || std::is_enum_v<T>,
                          "StateIO: a number, an enum, a container or a class with checkpoint()");
            transfer(name, &value, sizeof(T), 1);
        }
        return *this;
    }

    /// Saves or restores a large text (an output file) as a blob: with a store, the state holds
    /// its key and the store its contents, once for every state that has it; else as a member.
    StateIO& blob(const char* name, std::string& text);

    /// The saved bytes.
    const std::string& bytes() const { return bytes_; }
    /// Restoring: InputError unless every saved value was read.
    void expect_end() const;

private:
    /// Restoring: the element count of the next value, checking its name and element size.
    std::size_t count(const char* name, std::size_t element);
    /// Writes or reads `n` elements of `element` bytes under `name`.
    void transfer(const char* name, void* data, std::size_t element, std::size_t n);
    [[noreturn]] void fail(const std::string& what) const;

    bool restoring_ = false;
    BlobStore* blobs_ = nullptr;         // saving
    const BlobStore* stored_ = nullptr;  // restoring
    std::string bytes_;
    std::string source_;
    std::size_t at_ = 0;    // restoring: read position in bytes_
    bool counted_ = false;  // restoring: the current value's header has been read by count()
};

}  // namespace granseg
