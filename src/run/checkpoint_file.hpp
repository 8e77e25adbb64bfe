// Checkpoint files: a run's state on disk, written so that a kill at any moment leaves a whole
// file, and read so that a wrong file is refused before any of it is used (docs/checkpoints.md).
//
//   solves      nothing: writes and reads the bytes of a checkpoint
//   inputs      a Checkpoint (what wrote it, the time, named blocks of bytes: run/state_io.hpp)
//   outputs     the file; on reading, the Checkpoint or one InputError line naming the file
//   invariants  a file is replaced only by a whole new one (temporary file, fsync, rename, fsync
//               of the directory); a file is read only if its length and checksum match its
//               header and its format version is this one
//
// The file: text lines, then the payload (the blocks, binary):
//     granseg checkpoint
//     format 1
//     kind tumbler                      the scene kind
//     program 5d0c...                   the build (run/build_identity.hpp)
//     scene 81f2...                     the scene's fingerprint (SceneFile::fingerprint)
//     t 9.99969                         the time of the state (17 digits) and the steps to it
//     steps 12041
//     finished 0                        1: the run reached its t_end
//     payload 2416733                   the payload's length in bytes
//     checksum 3a5e...                  of everything above this line and the payload
// so `head -9 FILE` says what a checkpoint is.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace granseg {

/// The format version this build writes and reads.
constexpr int kCheckpointFormat = 1;

/// A 64-bit hash of `bytes` (FNV-1a over 64-bit words, then the remaining bytes): any change of a
/// single word changes it. For checksums and fingerprints, not for security.
std::uint64_t hash64(std::string_view bytes);
/// hash64 as 16 hex digits.
std::string hash_text(std::string_view bytes);

struct Checkpoint {
    std::string kind, program, scene;  // scene kind, build identity, scene fingerprint
    double t = 0.0;
    long steps = 0;
    bool finished = false;
    std::vector<std::pair<std::string, std::string>> blocks;  // name, bytes

    /// The bytes of block `name`; InputError naming `file` if there is none.
    const std::string& block(const std::string& name, const std::string& file) const;
    bool has(const std::string& name) const;
};

/// Writes `c` to `path` atomically (see above), creating the directory. On failure (directory not
/// writable, disk full) the file at `path` is left as it was and InputError says what happened.
void write_checkpoint(const std::string& path, const Checkpoint& c);

/// Reads the checkpoint at `path`: InputError (one line naming the file) for a file that is missing,
/// not a checkpoint, of another format version, truncated or corrupted.
Checkpoint read_checkpoint(const std::string& path);

}  // namespace granseg
