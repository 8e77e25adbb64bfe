#include "harness/doc_values.hpp"

#include "harness/doc_blocks.hpp"
#include "harness/doc_words.hpp"
#include "harness/text_pattern.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>

namespace fs = std::filesystem;

namespace granseg::verify::docs {

namespace {

const std::string kOpen = "<!-- value: ";
const std::string kOpenEnd = " -->";
const std::string kClose = "<!-- /value -->";

/// The cells of a markdown table row (without the outer bars).
std::vector<std::string> cells_of(const std::string& row) {
    std::vector<std::string> cells;
    std::string s = trimmed(row);
    if (!s.empty() && s.front() == '|') s.erase(0, 1);
    if (!s.empty() && s.back() == '|') s.pop_back();
    std::istringstream in(s);
    for (std::string c; std::getline(in, c, '|');) cells.push_back(trimmed(c));
    return cells;
}

std::optional<double> nth_number(const std::string& text, int n, std::string& error) {
    const std::vector<double> numbers = tokens_of(text).numbers;
    const long count = static_cast<long>(numbers.size());
    const long i = n > 0 ? n - 1 : count + n;
    if (n == 0 || i < 0 || i >= count) {
        error = "no number #" + std::to_string(n) + " in \"" + trimmed(text) + "\" (" + std::to_string(count) + " numbers)";
        return std::nullopt;
    }
    return numbers[static_cast<std::size_t>(i)];
}

std::optional<double> text_value(const ValueSource& s, const std::string& file_text, std::string& error) {
    const std::vector<std::string> lines = lines_of(file_text);
    int seen = 0;
    const auto hit = std::find_if(lines.begin(), lines.end(), [&](const std::string& l) {
        return l.find(s.match) != std::string::npos && ++seen == s.occurrence;
    });
    if (hit == lines.end()) {
        error = "no line " + std::to_string(s.occurrence) + " containing \"" + s.match + "\"";
        return std::nullopt;
    }
    if (s.column.empty()) return nth_number(hit->substr(hit->find(s.match) + s.match.size()), s.number, error);
    // The table's header: the first line of the block of table lines the row belongs to.
    auto header = hit;
    while (header != lines.begin() && trimmed(*(header - 1)).rfind('|', 0) == 0) --header;
    const std::vector<std::string> names = cells_of(*header), cells = cells_of(*hit);
    // The header equal to COLUMN, else the first that contains it.
    auto column = std::find(names.begin(), names.end(), s.column);
    if (column == names.end())
        column =
            std::find_if(names.begin(), names.end(), [&](const std::string& c) { return c.find(s.column) != std::string::npos; });
    if (trimmed(*hit).rfind('|', 0) != 0 || column == names.end()) {
        error = "no table column \"" + s.column + "\" for the line containing \"" + s.match + "\"";
        return std::nullopt;
    }
    const auto at = static_cast<std::size_t>(column - names.begin());
    if (at >= cells.size()) {
        error = "the row containing \"" + s.match + "\" has no cell under \"" + s.column + "\"";
        return std::nullopt;
    }
    return nth_number(cells[at], s.number, error);
}

std::optional<double> data_value(const ValueSource& s, const std::string& file_text, std::string& error) {
    std::vector<std::string> names;
    std::vector<std::vector<double>> rows;
    for (const std::string& line : lines_of(file_text)) {
        std::istringstream words(line);
        if (line.rfind('#', 0) == 0) {
            if (names.empty() && rows.empty()) {
                words.ignore(1);
                for (std::string w; words >> w;) names.push_back(w);
            }
            continue;
        }
        std::vector<double> row;
        for (std::string w; words >> w;) row.push_back(std::strtod(w.c_str(), nullptr));
        if (!row.empty()) rows.push_back(row);
    }
    const auto column_of = [&](const std::string& name) {
        return static_cast<long>(std::find(names.begin(), names.end(), name) - names.begin());
    };
    const long c = column_of(s.column);
    if (c == static_cast<long>(names.size())) {
        error = "no column \"" + s.column + "\" in the header line";
        return std::nullopt;
    }
    const std::vector<double>* row = nullptr;
    if (s.row == "last" && !rows.empty())
        row = &rows.back();
    else if (const auto eq = s.row.find('='); eq != std::string::npos) {
        const long k = column_of(s.row.substr(0, eq));
        const double want = std::strtod(s.row.c_str() + eq + 1, nullptr);
        for (const auto& r : rows)
            if (k < static_cast<long>(r.size()) && r[static_cast<std::size_t>(k)] == want) {
                row = &r;
                break;
            }
    } else if (s.row.find_first_not_of("0123456789") == std::string::npos && !s.row.empty()) {
        const std::size_t n = std::stoul(s.row);
        if (n >= 1 && n <= rows.size()) row = &rows[n - 1];
    }
    if (!row || c >= static_cast<long>(row->size())) {
        error = "no row " + s.row + " with column \"" + s.column + "\" (" + std::to_string(rows.size()) + " rows)";
        return std::nullopt;
    }
    return (*row)[static_cast<std::size_t>(c)];
}

}  // namespace

std::vector<ValueSpan> value_spans(const std::string& page, std::string& error) {
    std::vector<ValueSpan> spans;
    std::size_t line_start = 0;
    int number = 0;
    bool fenced = false;
    while (line_start < page.size()) {
        ++number;
        std::size_t line_end = page.find('\n', line_start);
        if (line_end == std::string::npos) line_end = page.size();
        const std::string line = page.substr(line_start, line_end - line_start);
        if (line.rfind("```", 0) == 0) fenced = !fenced;
        for (std::size_t at = fenced ? std::string::npos : line.find(kOpen); at != std::string::npos;
             at = line.find(kOpen, at + 1)) {
            const std::size_t source_end = line.find(kOpenEnd, at + kOpen.size());
            const std::size_t close = source_end == std::string::npos ? source_end : line.find(kClose, source_end);
            const std::string where = "line " + std::to_string(number) + ": ";
            if (close == std::string::npos) {
                if (error.empty()) error = where + "value span not closed on its line";
                break;
            }
            ValueSpan s;
            s.source = trimmed(line.substr(at + kOpen.size(), source_end - at - kOpen.size()));
            const std::size_t text_at = source_end + kOpenEnd.size();
            s.text = line.substr(text_at, close - text_at);
            s.line = number, s.offset = line_start + text_at;
            if ((s.source.empty() || s.text.empty()) && error.empty())
                error = where + "value span with an empty source or number";
            spans.push_back(s);
        }
        line_start = line_end + 1;
    }
    return spans;
}

std::optional<ValueSource> parse_source(const std::string& source, std::string& error) {
    // The column after a bar, or in brackets (a span inside a table row, where a bar would split the cell).
    static const Pattern text(
        R"re(^\s*(\S+)\s+"([^"]+)"(?:~(\d+))?\s*(?:\|\s*(.*?)|\[([^\]]*)\])?\s*(?:#(-?\d+))?\s*(?:([*/])\s*([0-9.eE+-]+))?\s*$)re");
    static const Pattern data(R"re(^\s*([^:\s]+):([^@\s]+)@(\S+)\s*(?:([*/])\s*([0-9.eE+-]+))?\s*$)re");
    ValueSource s;
    std::string op, factor;
    if (const auto m = text.match_of(source)) {
        s.file = (*m)[1], s.match = (*m)[2], s.column = trimmed(m->took_part[5] ? (*m)[5] : (*m)[4]);
        if (m->took_part[3]) s.occurrence = std::stoi((*m)[3]);
        if (m->took_part[6]) s.number = std::stoi((*m)[6]);
        op = (*m)[7], factor = (*m)[8];
    } else if (const auto d = data.match_of(source)) {
        s.data = true, s.file = (*d)[1], s.column = (*d)[2], s.row = (*d)[3], op = (*d)[4], factor = (*d)[5];
    } else {
        error = "not a value source (FILE \"MATCH\" [| COLUMN] [#N] [*K], or FILE:COLUMN@ROW [*K]): " + source;
        return std::nullopt;
    }
    if (!op.empty()) {
        char* end = nullptr;
        const double k = std::strtod(factor.c_str(), &end);
        if (*end != '\0' || !(k > 0.0) || !std::isfinite(k)) {
            error = "scale " + op + factor + " is not a positive number";
            return std::nullopt;
        }
        s.scale = op == "*" ? k : 1.0 / k;
    }
    if (s.file != "output" && s.file.rfind("docs/", 0) != 0 && s.file.rfind("build/", 0) != 0) {
        error = "source file " + s.file + " is neither under docs/ nor under build/, nor the output block above";
        return std::nullopt;
    }
    return s;
}

std::optional<double> source_value(const ValueSource& source, const std::string& file_text, std::string& error) {
    const auto v = source.data ? data_value(source, file_text, error) : text_value(source, file_text, error);
    if (v) return *v * source.scale;
    return v;
}

std::optional<ShownNumber> shown_number(const std::string& text) {
    static const Pattern plain(R"(^-?(\d+)(\.(\d+))?([eE]([-+]?\d+))?$)");
    static const Pattern grouped(R"(^-?\d{1,3}(,\d{3})+(\.(\d+))?$)");
    std::string s = text;
    if (grouped.matches(s)) s.erase(std::remove(s.begin(), s.end(), ','), s.end());
    const auto m = plain.match_of(s);
    if (!m) {
        const auto words = word_number(text);  // "twice", "a third" (doc_words.hpp)
        if (words) return ShownNumber{words->value, words->unit};
        return std::nullopt;
    }
    const int decimals = static_cast<int>((*m)[3].size()), exponent = m->took_part[5] ? std::stoi((*m)[5]) : 0;
    return ShownNumber{std::stod(s), std::pow(10.0, exponent - decimals)};
}

bool shows(const ShownNumber& shown, double value) { return within_last_digit(value, shown.value, shown.unit); }

std::string rendered_like(double value, const std::string& like) {
    if (const auto words = in_words_like(value, like)) return *words;
    const auto dot = like.find('.'), e = like.find_first_of("eE");
    const int decimals = dot == std::string::npos ? 0 : static_cast<int>((e == std::string::npos ? like.size() : e) - dot - 1);
    char buffer[64];
    std::string out;
    if (e != std::string::npos) {
        std::snprintf(buffer, sizeof buffer, "%.*e", decimals, value);
        out = buffer;
        const auto at = out.find('e');
        std::string mantissa = out.substr(0, at), exponent = out.substr(at + 1);
        const bool negative = exponent[0] == '-';
        exponent.erase(0, 1);
        const std::string written = like.substr(e + 1);
        const bool padded =
            written.find_first_of("0123456789") != std::string::npos && written[written.find_first_of("0123456789")] == '0';
        while (!padded && exponent.size() > 1 && exponent[0] == '0') exponent.erase(0, 1);
        out = mantissa + like[e] + (negative ? "-" : written[0] == '+' ? "+" : "") + exponent;
    } else {
        std::snprintf(buffer, sizeof buffer, "%.*f", decimals, value);
        out = buffer;
        if (like.find(',') != std::string::npos) {
            const std::size_t sign = out[0] == '-' ? 1 : 0, end = out.find('.') == std::string::npos ? out.size() : out.find('.');
            for (std::size_t i = end; i > sign + 3; i -= 3) out.insert(i - 3, ",");
        }
    }
    const std::size_t mantissa_end = std::min(out.size(), out.find_first_of("eE"));
    if (out[0] == '-' && out.find_first_of("123456789") >= mantissa_end) out.erase(0, 1);  // no "-0.000"
    return out;
}

std::string with_values(const std::string& page, const std::vector<ResolvedSpan>& spans, int& changed) {
    std::string out = page;
    changed = 0;
    for (auto r = spans.rbegin(); r != spans.rend(); ++r) {  // from the end: earlier offsets stay valid
        if (!r->value) continue;
        const std::string now = rendered_like(*r->value, r->span.text);
        if (now == r->span.text) continue;
        out.replace(r->span.offset, r->span.text.size(), now);
        ++changed;
    }
    return out;
}

namespace {

/// The text of the last output block that ends before `line` (1-based) of the page, or nothing.
std::optional<std::string> output_block_before(const std::string& page, int line) {
    std::optional<std::string> text;
    for (const Block& b : fenced_blocks(page)) {
        if (b.first_line + static_cast<int>(b.lines.size()) + 1 >= line) break;
        if (b.language != "output") continue;
        text = "";
        for (const std::string& l : b.lines) *text += l + "\n";
    }
    return text;
}

std::optional<double> resolved(const std::string& source_text, const std::string& page, int line, const fs::path& root,
                               const fs::path& build, std::string& error) {
    const auto source = parse_source(source_text, error);
    if (!source) return std::nullopt;
    if (source->file == "output") {
        const auto block = output_block_before(page, line);
        if (block) return source_value(*source, *block, error);
        error = "no output block above the span";
        return std::nullopt;
    }
    const fs::path file = source->file.rfind("build/", 0) == 0 ? build / source->file.substr(6) : root / source->file;
    bool found = false;
    const std::string text = read_text(file, &found);
    if (found) return source_value(*source, text, error);
    error = "no file " + source->file + (source->file.rfind("build/", 0) == 0 ? " (run make verify first)" : "");
    return std::nullopt;
}

}  // namespace

std::vector<ResolvedSpan> resolved_spans(const std::string& page, const fs::path& root, const fs::path& build,
                                         std::string& error) {
    std::vector<ResolvedSpan> out;
    static const Pattern power(R"(^(.*\S)\s+\^\s*([0-9.]+)\s*$)");
    for (ValueSpan span : value_spans(page, error)) {
        ResolvedSpan r{span, std::nullopt, ""};
        // SOURCE ^ K: the value to the power K (a ratio of temperatures as one of speeds: ^ 0.5).
        double exponent = 1.0;
        if (const auto m = power.match_of(span.source)) span.source = (*m)[1], exponent = std::stod((*m)[2]);
        // SOURCE - SOURCE, SOURCE + SOURCE, SOURCE / SOURCE: the difference, sum or ratio of two values.
        std::size_t op = std::string::npos;
        for (const char* sign : {" - ", " + ", " / "})
            for (const char* next : {"docs/", "build/", "output "}) op = std::min(op, span.source.find(sign + std::string(next)));
        if (op == std::string::npos) {
            r.value = resolved(span.source, page, span.line, root, build, r.error);
        } else {
            const auto a = resolved(span.source.substr(0, op), page, span.line, root, build, r.error);
            const auto b = a ? resolved(span.source.substr(op + 3), page, span.line, root, build, r.error) : std::nullopt;
            const char sign = span.source[op + 1];
            if (a && b) r.value = sign == '-' ? *a - *b : sign == '+' ? *a + *b : *a / *b;
        }
        if (r.value && exponent != 1.0) r.value = std::pow(*r.value, exponent);
        out.push_back(r);
    }
    return out;
}

}  // namespace granseg::verify::docs
