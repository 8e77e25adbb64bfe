#include "run/expression.hpp"

#include "core/error.hpp"
#include "core/format.hpp"

#include <muParser.h>

#include <algorithm>

namespace granseg {

struct Expression::Impl {
    mu::Parser parser;
    std::vector<double> storage;  // muparser reads the variables through these addresses
};

Expression::Expression(const std::string& text, const std::vector<std::string>& variables)
    : text_(text), variables_(variables), impl_(std::make_unique<Impl>()) {
    impl_->storage.assign(variables_.size(), 0.0);
    try {
        for (std::size_t i = 0; i < variables_.size(); ++i) impl_->parser.DefineVar(variables_[i], &impl_->storage[i]);
        impl_->parser.SetExpr(text_);
        // GetUsedVar parses with undefined names allowed, so an unknown name is reported as
        // such instead of as muparser's generic "unexpected token".
        for (const auto& used : impl_->parser.GetUsedVar()) {
            if (std::find(variables_.begin(), variables_.end(), used.first) == variables_.end())
                throw InputError("unknown variable \"" + used.first + "\" (variables: " + comma_list(variables_) + ")");
        }
        impl_->parser.Eval();  // surfaces remaining syntax errors now, not at first use
    } catch (const mu::Parser::exception_type& e) {
        throw InputError("malformed expression \"" + text_ + "\": " + e.GetMsg());
    }
}

Expression::Expression(const Expression& other) : Expression(other.text_, other.variables_) {}

Expression& Expression::operator=(const Expression& other) {
    if (this != &other) *this = Expression(other);
    return *this;
}

Expression::Expression(Expression&&) noexcept = default;
Expression& Expression::operator=(Expression&&) noexcept = default;
Expression::~Expression() = default;

double Expression::operator()(const std::vector<double>& values) const {
    if (values.size() != variables_.size())
        throw InputError("expression \"" + text_ + "\" needs " + std::to_string(variables_.size()) + " values");
    std::copy(values.begin(), values.end(), impl_->storage.begin());
    return impl_->parser.Eval();
}

}  // namespace granseg
