#include "harness/table_provenance.hpp"

#include "core/error.hpp"
#include "run/output.hpp"

#include <cstdio>
#include <memory>
#include <sstream>

namespace fs = std::filesystem;

namespace granseg::verify {

const std::vector<std::string> kDrumParts = {"flow", "drum", "segregation", "closures"};
const std::vector<std::string> kDrumStudyParts = {"flow", "drum", "segregation", "closures", "study"};

namespace {

const std::string kOpen = "<!-- provenance";
const std::string kClose = "-->";

struct Invocation {
    std::string argv0 = "", command = "", commit = "";
};
Invocation& invocation() {
    static Invocation i;
    return i;
}

/// The first line of what `command` prints ("" if it fails).
std::string first_line_of(const std::string& command) {
    std::unique_ptr<FILE, int (*)(FILE*)> pipe(popen(command.c_str(), "r"), pclose);
    if (!pipe) return "";
    std::string out;
    char buf[256];
    while (std::fgets(buf, sizeof buf, pipe.get())) out += buf;
    return out.substr(0, out.find('\n'));
}

/// The position of the record's first line in a table's text, or npos.
std::size_t record_start(const std::string& text) {
    const std::size_t at = text.rfind("\n" + kOpen + "\n");
    if (at != std::string::npos) return at + 1;
    return text.rfind(kOpen + "\n", 0) == 0 ? 0 : std::string::npos;
}

}  // namespace

std::string physics_line(const Fingerprints& physics) {
    std::string line;
    for (const auto& [part, fingerprint] : physics) line += (line.empty() ? "" : " ") + part + "=" + fingerprint;
    return line;
}

std::string provenance_record(const Provenance& p) {
    return kOpen + "\nprogram: " + p.program + "\ncommand: " + p.command + "\ncommit: " + p.commit +
           "\nphysics: " + physics_line(p.physics) + "\n" + kClose + "\n";
}

std::optional<Provenance> parse_provenance(const std::string& table_text) {
    const std::size_t at = record_start(table_text);
    if (at == std::string::npos) return std::nullopt;
    Provenance p;
    std::istringstream in(table_text.substr(at + kOpen.size() + 1));
    bool closed = false;
    for (std::string line; std::getline(in, line);) {
        if (line == kClose) {
            closed = true;
            break;
        }
        const auto colon = line.find(": ");
        const std::string key = line.substr(0, colon), value = colon == std::string::npos ? "" : line.substr(colon + 2);
        if (key == "program") p.program = value;
        if (key == "command") p.command = value;
        if (key == "commit") p.commit = value;
        if (key != "physics") continue;
        std::istringstream words(value);
        for (std::string w; words >> w;) {
            const auto eq = w.find('=');
            if (eq != std::string::npos) p.physics[w.substr(0, eq)] = w.substr(eq + 1);
        }
    }
    if (!closed || p.program.empty() || p.physics.empty()) return std::nullopt;
    return p;
}

std::string shown_part(const std::string& table_text) {
    const std::size_t at = record_start(table_text);
    return at == std::string::npos ? table_text : table_text.substr(0, at);
}

std::vector<std::string> physics_changes(const Fingerprints& recorded, const Fingerprints& now) {
    // In the order of physics_parts (the flow step first), then any part this build does not know.
    std::vector<std::pair<std::string, std::string>> parts;
    for (const PhysicsPart& p : physics_parts())
        if (recorded.count(p.name)) parts.emplace_back(p.name, recorded.at(p.name));
    for (const auto& [part, fingerprint] : recorded)
        if (part_title(part) == part) parts.emplace_back(part, fingerprint);
    std::vector<std::string> out;
    for (const auto& [part, fingerprint] : parts) {
        const auto it = now.find(part);
        const std::string current = it == now.end() ? "none" : it->second;
        if (fingerprint == "unknown")
            out.push_back(part_title(part) + ": not recorded (the table predates provenance records)");
        else if (fingerprint != current)
            out.push_back(part_title(part) + " (recorded " + fingerprint + ", this build " + current + ")");
    }
    return out;
}

void remember_command_line(int argc, char** argv) {
    Invocation& i = invocation();
    i.argv0 = argc > 0 ? argv[0] : "";
    i.command.clear();
    for (int k = 0; k < argc; ++k) i.command += (k ? " " : "") + std::string(argv[k]);
    i.commit = commit_of(repository_root(i.argv0));
}

std::string commit_of(const fs::path& root) {
    const std::string git = "git -C '" + root.string() + "' ";
    const std::string hash = first_line_of(git + "rev-parse --short=12 HEAD 2>/dev/null");
    if (hash.empty()) return "unknown";
    const bool dirty = !first_line_of(git + "status --porcelain --untracked-files=no 2>/dev/null").empty();
    return hash + (dirty ? " (uncommitted changes)" : "");
}

fs::path repository_root(const std::string& argv0) {
    const auto holds = [](const fs::path& p) { return fs::exists(p / "verification" / "scenes" / "physics_flow.toml"); };
    if (!argv0.empty())
        for (fs::path p = fs::absolute(fs::path(argv0)).parent_path(); !p.empty(); p = p.parent_path()) {
            if (holds(p)) return p;
            if (p == p.parent_path()) break;
        }
    return fs::current_path();
}

namespace {

const Fingerprints& this_build_physics() {
    static const Fingerprints now = physics_fingerprints(repository_root(invocation().argv0));
    return now;
}

}  // namespace

std::string this_build_physics_line() { return physics_line(this_build_physics()); }

void write_generated_table(const std::string& path, const std::string& markdown, const std::vector<std::string>& parts) {
    const Invocation& i = invocation();
    const Fingerprints& now = this_build_physics();
    Provenance p{fs::path(i.argv0).filename().string(), i.command, i.commit.empty() ? "unknown" : i.commit, {}};
    for (const std::string& part : parts) {
        const auto it = now.find(part);
        if (it == now.end()) throw InputError("write_generated_table: no physics part " + part);
        p.physics[part] = it->second;
    }
    const bool ends_line = !markdown.empty() && markdown.back() == '\n';
    write_file_atomically(path, markdown + (ends_line ? "" : "\n") + provenance_record(p));
}

}  // namespace granseg::verify
