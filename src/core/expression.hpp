#pragma once
// A small arithmetic expression of the coordinates x, y, z, read from a case file (e.g. an initial
// velocity field) and evaluated per node. Numbers, x y z, pi, + - * / ^ (right-associative,
// binding tighter than a unary minus: -x^2 = -(x^2)), parentheses and the functions sin cos tan
// asin acos atan exp log sqrt abs. Nothing else: an expression cannot run code.
#include <string>
#include <string_view>
#include <vector>

namespace sf {

class Expression {
 public:
  /// The constant 0.
  Expression();
  /// Parses `text`; throws InputError saying where (1-based character) and what was expected.
  static Expression parse(std::string_view text);
  /// A constant.
  static Expression constant(double value);

  /// The value at (x, y, z).
  double evaluate(double x, double y, double z) const;
  /// The text it was parsed from (a constant: its shortest round-trip decimal form).
  const std::string& text() const { return text_; }
  bool is_constant() const { return code_.size() == 1 && code_[0].op == Op::number; }

  enum class Op { number, x, y, z, add, sub, mul, div, pow, neg, call };
  /// One instruction of the stack machine the text compiles to (postfix order).
  struct Instruction {
    Op op;
    double value = 0.0;          ///< Op::number
    double (*function)(double);  ///< Op::call
  };

 private:
  std::string text_;
  std::vector<Instruction> code_;
  friend class ExpressionParser;
};

}  // namespace sf
