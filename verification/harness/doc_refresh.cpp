#include "harness/doc_refresh.hpp"

#include "harness/doc_blocks.hpp"
#include "harness/doc_excerpts.hpp"
#include "harness/doc_provenance.hpp"
#include "harness/doc_values.hpp"
#include "harness/table_provenance.hpp"

#include <iostream>

#include "run/output.hpp"

namespace fs = std::filesystem;

namespace granseg::verify::docs {

fs::path fresh_table(const fs::path& build, const std::string& name) {
    for (const char* dir : {"data", "bench-data", "runs"})
        if (fs::exists(build / dir / name)) return build / dir / name;
    return {};
}

bool compared(const std::string& name) { return name.size() < 8 || name.compare(name.size() - 8, 8, "_cost.md") != 0; }

int refresh_pages(const fs::path& root, const fs::path& build, const std::vector<std::string>& pages, const Fingerprints& now) {
    for (const auto& e : fs::directory_iterator(root / "docs" / "generated")) {
        const std::string name = e.path().filename().string();
        const fs::path fresh = fresh_table(build, name);
        if (fresh.empty()) continue;
        const std::string text = read_text(fresh);
        write_file_atomically(e.path().string(), text);
        for (const std::string& page : pages) {
            const std::string before = read_text(root / page), after = with_generated(before, name, shown_part(text));
            if (after != before) write_file_atomically((root / page).string(), after);
        }
        std::cout << "docs-refresh: " << name << " from " << fresh.string() << " (" << physics_verdict(text, now) << ")\n";
    }
    // Excerpts that no longer match their code: the whole definition, for the author to trim again.
    for (const std::string& page : pages) {
        int rewritten = 0;
        const std::string before = read_text(root / page), after = with_fresh_excerpts(before, root, rewritten);
        if (rewritten == 0) continue;
        write_file_atomically((root / page).string(), after);
        std::cout << "docs-refresh: " << page << ": " << rewritten
                  << " code excerpts shown whole; trim them again with ... lines\n";
    }
    // Spans last: those that read a generated table then see its fresh copy.
    for (const std::string& page : pages) {
        std::string error;
        const std::string text = read_text(root / page);
        const auto spans = resolved_spans(text, root, build, error);
        if (!error.empty()) std::cout << "docs-refresh: " << page << ": " << error << '\n';
        for (const ResolvedSpan& r : spans)
            if (!r.value) std::cout << "docs-refresh: " << page << " line " << r.span.line << ": kept (" << r.error << ")\n";
        int changed = 0;
        const std::string after = with_values(text, spans, changed);
        if (changed == 0) continue;
        write_file_atomically((root / page).string(), after);
        std::cout << "docs-refresh: " << page << ": " << changed << " value spans rewritten\n";
    }
    return 0;
}

}  // namespace granseg::verify::docs
