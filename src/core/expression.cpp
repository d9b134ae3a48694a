#include "core/expression.hpp"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <utility>

#include "core/errors.hpp"

namespace sf {

class ExpressionParser {
 public:
  explicit ExpressionParser(std::string_view text) : text_(text) {}

  std::vector<Expression::Instruction> compile() {
    expression();
    skip_blanks();
    if (pos_ < text_.size()) {
      fail("an operator or the end of the expression");
    }
    return std::move(code_);
  }

 private:
  using Op = Expression::Op;

  void expression() {  // term (('+' | '-') term)*
    term();
    while (true) {
      if (accept('+')) {
        term();
        emit(Op::add);
      } else if (accept('-')) {
        term();
        emit(Op::sub);
      } else {
        return;
      }
    }
  }

  void term() {  // unary (('*' | '/') unary)*
    unary();
    while (true) {
      if (accept('*')) {
        unary();
        emit(Op::mul);
      } else if (accept('/')) {
        unary();
        emit(Op::div);
      } else {
        return;
      }
    }
  }

  void unary() {  // ('-' | '+') unary | power
    if (accept('-')) {
      unary();
      emit(Op::neg);
    } else if (accept('+')) {
      unary();
    } else {
      power();
    }
  }

  void power() {  // primary ('^' unary)?
    primary();
    if (accept('^')) {
      unary();
      emit(Op::pow);
    }
  }

  void primary() {
    skip_blanks();
    if (accept('(')) {
      expression();
      expect(')');
      return;
    }
    if (pos_ < text_.size() &&
        (std::isdigit(static_cast<unsigned char>(text_[pos_])) || text_[pos_] == '.')) {
      number();
      return;
    }
    const std::string_view name = identifier();
    if (name.empty()) {
      fail("a number, x, y, z, pi, a function or '('");
    }
    if (name == "x" || name == "y" || name == "z") {
      emit(name == "x" ? Op::x : (name == "y" ? Op::y : Op::z));
    } else if (name == "pi") {
      code_.push_back({Op::number, std::numbers::pi, nullptr});
    } else if (double (*f)(double) = function(name)) {
      expect('(');
      expression();
      expect(')');
      code_.push_back({Op::call, 0.0, f});
    } else {
      pos_ -= name.size();
      fail(
          "x, y, z, pi or one of the functions sin, cos, tan, asin, acos, atan, exp, log, sqrt, "
          "abs (got '" +
          std::string(name) + "')");
    }
  }

  static double (*function(std::string_view name))(double) {
    static const std::pair<std::string_view, double (*)(double)> table[] = {
        {"sin", [](double v) { return std::sin(v); }},
        {"cos", [](double v) { return std::cos(v); }},
        {"tan", [](double v) { return std::tan(v); }},
        {"asin", [](double v) { return std::asin(v); }},
        {"acos", [](double v) { return std::acos(v); }},
        {"atan", [](double v) { return std::atan(v); }},
        {"exp", [](double v) { return std::exp(v); }},
        {"log", [](double v) { return std::log(v); }},
        {"sqrt", [](double v) { return std::sqrt(v); }},
        {"abs", [](double v) { return std::abs(v); }}};
    for (const auto& [key, f] : table) {
      if (key == name) {
        return f;
      }
    }
    return nullptr;
  }

  void number() {
    double value = 0.0;
    const char* begin = text_.data() + pos_;
    const auto [end, ec] = std::from_chars(begin, text_.data() + text_.size(), value);
    if (ec != std::errc() || end == begin) {
      fail("a number");
    }
    pos_ += static_cast<std::size_t>(end - begin);
    code_.push_back({Op::number, value, nullptr});
  }

  std::string_view identifier() {
    const std::size_t start = pos_;
    while (pos_ < text_.size() && std::isalpha(static_cast<unsigned char>(text_[pos_]))) {
      ++pos_;
    }
    return text_.substr(start, pos_ - start);
  }

  void skip_blanks() {
    while (pos_ < text_.size() && std::isspace(static_cast<unsigned char>(text_[pos_]))) {
      ++pos_;
    }
  }
  bool accept(char c) {
    skip_blanks();
    if (pos_ < text_.size() && text_[pos_] == c) {
      ++pos_;
      return true;
    }
    return false;
  }
  void expect(char c) {
    if (!accept(c)) {
      fail(std::string("'") + c + "'");
    }
  }
  void emit(Op op) { code_.push_back({op, 0.0, nullptr}); }

  [[noreturn]] void fail(const std::string& expected) const {
    throw InputError("in the expression \"" + std::string(text_) + "\" at character " +
                     std::to_string(pos_ + 1) + ": expected " + expected);
  }

  std::string_view text_;
  std::size_t pos_ = 0;
  std::vector<Expression::Instruction> code_;
};

namespace {

// The deepest the evaluation stack gets for this code.
int stack_depth(const std::vector<Expression::Instruction>& code) {
  int depth = 0;
  int deepest = 0;
  for (const Expression::Instruction& in : code) {
    const bool push = in.op == Expression::Op::number || in.op == Expression::Op::x ||
                      in.op == Expression::Op::y || in.op == Expression::Op::z;
    const bool unary = in.op == Expression::Op::neg || in.op == Expression::Op::call;
    depth += push ? 1 : (unary ? 0 : -1);
    deepest = std::max(deepest, depth);
  }
  return deepest;
}

constexpr int kMaxDepth = 64;

}  // namespace

Expression Expression::parse(std::string_view text) {
  Expression e;
  e.text_ = std::string(text);
  e.code_ = ExpressionParser(text).compile();
  if (stack_depth(e.code_) > kMaxDepth) {
    throw InputError("the expression \"" + e.text_ + "\" nests too deeply (more than " +
                     std::to_string(kMaxDepth) + " pending values)");
  }
  return e;
}

Expression::Expression() : text_("0"), code_{{Op::number, 0.0, nullptr}} {}

Expression Expression::constant(double value) {
  Expression e;
  char buffer[32];
  const auto result = std::to_chars(buffer, buffer + sizeof buffer, value);
  e.text_ = std::string(buffer, result.ptr);
  e.code_ = {{Op::number, value, nullptr}};
  return e;
}

double Expression::evaluate(double x, double y, double z) const {
  double stack[kMaxDepth];  // parse() rejected deeper code
  int top = 0;
  for (const Instruction& in : code_) {
    switch (in.op) {
      case Op::number:
        stack[top++] = in.value;
        break;
      case Op::x:
        stack[top++] = x;
        break;
      case Op::y:
        stack[top++] = y;
        break;
      case Op::z:
        stack[top++] = z;
        break;
      case Op::neg:
        stack[top - 1] = -stack[top - 1];
        break;
      case Op::call:
        stack[top - 1] = in.function(stack[top - 1]);
        break;
      default: {
        const double b = stack[--top];
        double& a = stack[top - 1];
        a = in.op == Op::add   ? a + b
            : in.op == Op::sub ? a - b
            : in.op == Op::mul ? a * b
            : in.op == Op::div ? a / b
                               : std::pow(a, b);
      }
    }
  }
  return stack[0];
}

}  // namespace sf
