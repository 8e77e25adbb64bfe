#include "run/checkpoint_file.hpp"

#include "core/error.hpp"
#include "core/format.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

namespace granseg {

namespace {

constexpr std::uint64_t kFnvOffset = 14695981039346656037ull, kFnvPrime = 1099511628211ull;

void append_u64(std::string& out, std::uint64_t v) { out.append(reinterpret_cast<const char*>(&v), sizeof v); }

/// Writes all of `bytes` to fd; false (errno set) on failure.
bool write_all(int fd, std::string_view bytes) {
    while (!bytes.empty()) {
        const ssize_t n = ::write(fd, bytes.data(), bytes.size());
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) return false;
        bytes.remove_prefix(static_cast<std::size_t>(n));
    }
    return true;
}

/// The header lines above the checksum line.
std::string head_of(const Checkpoint& c, std::size_t payload) {
    const std::string t = format_exact(c.t);
    return "granseg checkpoint\nformat " + std::to_string(kCheckpointFormat) + "\nkind " + c.kind + "\nprogram " + c.program +
           "\nscene " + c.scene + "\nt " + t + "\nsteps " + std::to_string(c.steps) + "\nfinished " + (c.finished ? "1" : "0") +
           "\npayload " + std::to_string(payload) + "\n";
}

/// The checksum line's value: of the header above it and of the payload (each part's hash64; a
/// change of either changes it).
std::string checksum_of(std::string_view head, std::string_view payload) {
    const std::uint64_t both[2] = {hash64(head), hash64(payload)};
    return hash_text(std::string_view(reinterpret_cast<const char*>(both), sizeof both));
}

}  // namespace

std::uint64_t hash64(std::string_view bytes) {
    std::uint64_t h = kFnvOffset;
    std::size_t i = 0;
    for (; i + 8 <= bytes.size(); i += 8) {
        std::uint64_t word;
        std::memcpy(&word, bytes.data() + i, 8);
        h = (h ^ word) * kFnvPrime;
    }
    for (; i < bytes.size(); ++i) h = (h ^ static_cast<unsigned char>(bytes[i])) * kFnvPrime;
    return h;
}

std::string hash_text(std::string_view bytes) {
    char out[17];
    std::snprintf(out, sizeof out, "%016llx", static_cast<unsigned long long>(hash64(bytes)));
    return out;
}

const std::string& Checkpoint::block(const std::string& name, const std::string& file) const {
    for (const auto& [n, bytes] : blocks)
        if (n == name) return bytes;
    throw InputError(file + ": no \"" + name + "\" in this checkpoint (allowed: a checkpoint of this scene kind)");
}

bool Checkpoint::has(const std::string& name) const {
    for (const auto& b : blocks)
        if (b.first == name) return true;
    return false;
}

void write_checkpoint(const std::string& path, const Checkpoint& c) {
    namespace fs = std::filesystem;
    std::string payload;
    for (const auto& [name, bytes] : c.blocks) {
        append_u64(payload, name.size());
        payload += name;
        append_u64(payload, bytes.size());
        payload += bytes;
    }
    const std::string head = head_of(c, payload.size());
    const std::string sum = "checksum " + checksum_of(head, payload) + "\n";

    const fs::path target(path);
    const fs::path dir = target.has_parent_path() ? target.parent_path() : fs::path(".");
    std::error_code ec;
    fs::create_directories(dir, ec);
    const auto fail = [&](const std::string& what) {
        throw InputError("cannot write the checkpoint " + path + ": " + what +
                         (fs::exists(target) ? " (the previous checkpoint there is kept)" : ""));
    };
    if (ec) fail("cannot create the directory " + dir.string() + ": " + ec.message());
    const std::string tmp = path + ".tmp." + std::to_string(::getpid());
    const int fd = ::open(tmp.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
    if (fd < 0) fail(std::strerror(errno));
    const bool ok = write_all(fd, head) && write_all(fd, sum) && write_all(fd, payload) && ::fsync(fd) == 0;
    const int error = errno;
    if (::close(fd) != 0 || !ok) {
        ::unlink(tmp.c_str());
        fail(std::strerror(ok ? errno : error));
    }
    if (::rename(tmp.c_str(), path.c_str()) != 0) {
        const int e = errno;
        ::unlink(tmp.c_str());
        fail(std::strerror(e));
    }
    // The rename itself reaches the disk with the directory's entry.
    const int dfd = ::open(dir.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
    if (dfd >= 0) ::fsync(dfd), ::close(dfd);
}

namespace {

/// The named blocks of a checkpoint's payload: each its name's size, its name, its size and its
/// bytes (sizes as 8-byte integers). InputError naming `path` if one overruns the payload.
decltype(Checkpoint::blocks) blocks_of(std::string_view body, const std::string& path) {
    decltype(Checkpoint::blocks) blocks;
    std::size_t p = 0;
    const auto need = [&](std::uint64_t bytes) {
        if (body.size() - p < bytes)
            throw InputError(path +
                             ": corrupted: its blocks overrun the payload (allowed: a whole checkpoint written by granseg run)");
    };
    const auto take_u64 = [&] {
        std::uint64_t v = 0;
        need(sizeof v);
        std::memcpy(&v, body.data() + p, sizeof v);
        p += sizeof v;
        return v;
    };
    while (p < body.size()) {
        const std::uint64_t name_size = take_u64();
        need(name_size);
        std::string name(body.substr(p, name_size));
        p += name_size;
        const std::uint64_t size = take_u64();
        need(size);
        blocks.emplace_back(std::move(name), std::string(body.substr(p, size)));
        p += size;
    }
    return blocks;
}

}  // namespace

Checkpoint read_checkpoint(const std::string& path) {
    const auto fail = [&](const std::string& what) -> InputError {
        return InputError(path + ": " + what + " (allowed: a whole checkpoint written by granseg run)");
    };
    std::ifstream in(path, std::ios::binary);
    if (!in) throw fail("cannot open the checkpoint");
    std::ostringstream all;
    all << in.rdbuf();
    const std::string text = all.str();

    // The header: "name value" lines up to the checksum line.
    std::map<std::string, std::string> field;
    std::size_t at = 0, checksum_line = std::string::npos;
    for (int line = 0; line < 16 && at < text.size(); ++line) {
        const std::size_t end = text.find('\n', at);
        if (end == std::string::npos) break;
        const std::string l = text.substr(at, end - at);
        if (line == 0 && l != "granseg checkpoint") break;
        const std::size_t space = l.find(' ');
        if (line > 0) field[l.substr(0, space)] = space == std::string::npos ? "" : l.substr(space + 1);
        if (l.rfind("checksum ", 0) == 0) checksum_line = at;
        at = end + 1;
        if (checksum_line != std::string::npos) break;
    }
    if (text.rfind("granseg checkpoint\n", 0) != 0) throw fail("not a granseg checkpoint");
    if (checksum_line == std::string::npos) throw fail("truncated inside its header");
    if (field["format"] != std::to_string(kCheckpointFormat))
        throw fail("checkpoint format " + field["format"] + ", this granseg reads format " + std::to_string(kCheckpointFormat));
    const std::size_t payload = std::strtoull(field["payload"].c_str(), nullptr, 10);
    if (text.size() - at < payload)
        throw fail("truncated: " + std::to_string(text.size() - at) + " of its " + std::to_string(payload) + " bytes of state");
    if (text.size() - at > payload)
        throw fail("corrupted: " + std::to_string(text.size() - at - payload) + " bytes more than its header says");
    const std::string_view body(text.data() + at, payload);
    if (checksum_of(std::string_view(text).substr(0, checksum_line), body) != field["checksum"])
        throw fail("corrupted: its checksum does not match its contents");

    Checkpoint c;
    c.kind = field["kind"], c.program = field["program"], c.scene = field["scene"];
    c.t = std::strtod(field["t"].c_str(), nullptr);
    c.steps = std::strtol(field["steps"].c_str(), nullptr, 10);
    c.finished = field["finished"] == "1";
    c.blocks = blocks_of(body, path);
    return c;
}

}  // namespace granseg
