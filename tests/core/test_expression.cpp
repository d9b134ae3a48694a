// Expression: the coordinate expressions of case files (an initial velocity field).
#include "core/expression.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>

#include "core/errors.hpp"

namespace {

double eval(const std::string& text, double x = 0.0, double y = 0.0, double z = 0.0) {
  return sf::Expression::parse(text).evaluate(x, y, z);
}

std::string error_of(const std::string& text) {
  try {
    sf::Expression::parse(text);
  } catch (const sf::InputError& e) {
    return e.what();
  }
  return "";
}

TEST(Expression, ArithmeticFollowsTheUsualPrecedence) {
  // Exact in binary floating point: compared with ==.
  EXPECT_EQ(eval("1 + 2 * 3"), 7.0);
  EXPECT_EQ(eval("(1 + 2) * 3"), 9.0);
  EXPECT_EQ(eval("8 / 4 / 2"), 1.0);    // left-associative
  EXPECT_EQ(eval("2 ^ 3 ^ 2"), 512.0);  // right-associative
  EXPECT_EQ(eval("-2 ^ 2"), -4.0);      // -(2^2)
  EXPECT_EQ(eval("2 ^ -1"), 0.5);
  EXPECT_EQ(eval("1 - 2 - 3"), -4.0);
  EXPECT_EQ(eval("--3"), 3.0);
  EXPECT_EQ(eval("1.5e3 + .5"), 1500.5);
  EXPECT_EQ(eval("x + 2 * y - z", 1.0, 2.0, 3.0), 2.0);
}

TEST(Expression, FunctionsAndPiMatchTheLibrary) {
  const double x = 37.0, y = 12.5;
  EXPECT_EQ(
      eval("20000 * sin(pi * x / 100) * sin(pi * y / 100)", x, y),
      20000.0 * std::sin(std::numbers::pi * x / 100.0) * std::sin(std::numbers::pi * y / 100.0));
  EXPECT_EQ(eval("sqrt(abs(-16)) + exp(0) + log(1) + cos(0) + tan(0)"), 6.0);
  EXPECT_EQ(eval("atan(1) * 4"), std::atan(1.0) * 4.0);
  EXPECT_EQ(eval("asin(1) + acos(1)"), std::asin(1.0));
  EXPECT_TRUE(sf::Expression::constant(2.5).is_constant());
  EXPECT_EQ(sf::Expression::constant(2.5).text(), "2.5");
  EXPECT_FALSE(sf::Expression::parse("x").is_constant());
}

TEST(Expression, ErrorsSayWhereAndWhat) {
  EXPECT_NE(error_of("1 +").find("at character 4: expected a number, x, y, z, pi"),
            std::string::npos)
      << error_of("1 +");
  EXPECT_NE(error_of("sin(x").find("expected ')'"), std::string::npos);
  EXPECT_NE(error_of("2 x").find("at character 3: expected an operator or the end"),
            std::string::npos)
      << error_of("2 x");
  EXPECT_NE(error_of("system(1)").find("got 'system'"), std::string::npos);
  EXPECT_NE(error_of("t * 2").find("got 't'"), std::string::npos);
  EXPECT_NE(error_of("").find("expected a number"), std::string::npos);
  EXPECT_NE(error_of("1 $ 2").find("character 3"), std::string::npos);
  std::string deep;
  for (int i = 0; i < 70; ++i) {
    deep += "1+(";
  }
  deep += "1" + std::string(70, ')');
  EXPECT_NE(error_of(deep).find("nests too deeply"), std::string::npos);
}

}  // namespace
