// The expression language: parsing with located errors, folding, point and
// interval evaluation, derivatives, OpenCL text and the flattened tape.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "sdfc/expr/expr.hpp"
#include "sdfc/expr/tape.hpp"

namespace sdfc::expr {
namespace {

const std::vector<std::string> kTime{"time"};
const std::vector<std::string> kXyz{"x", "y", "z", "time"};
SourceLoc at(int column) { return {std::make_shared<const std::string>("s.yaml"), 4, column}; }

ExprPtr p(const std::string& s, const std::vector<std::string>& vars = kXyz) { return parse(s, at(10), vars); }

Diagnostic error_of(const std::string& s, const std::vector<std::string>& vars = kTime) {
  try {
    parse(s, at(10), vars);
  } catch (const SceneError& e) {
    return e.diagnostics().front();
  }
  ADD_FAILURE() << "accepted: " << s;
  return {};
}

TEST(ExprParse, PrecedenceAndAssociativity) {
  EXPECT_EQ(to_string(p("1 + 2 * 3")), "(1 + (2 * 3))");
  EXPECT_EQ(to_string(p("2 ^ 3 ^ 2")), "(2 ^ (3 ^ 2))");
  EXPECT_EQ(to_string(p("-2 ^ 2")), "(-(2 ^ 2))");
  EXPECT_EQ(to_string(p("(1 + 2) * 3")), "((1 + 2) * 3)");
  EXPECT_EQ(to_string(p("8 + 0.5*sin(time)")), "(8 + (0.5 * sin(time)))");
  EXPECT_DOUBLE_EQ(evaluate(p("2 ^ 3 ^ 2"), {}), 512);
  EXPECT_DOUBLE_EQ(evaluate(p("-2 ^ 2"), {}), -4);
  EXPECT_DOUBLE_EQ(evaluate(p("10 - 4 - 3"), {}), 3);
  EXPECT_DOUBLE_EQ(evaluate(p("1.5e1 / 3"), {}), 5);
}

TEST(ExprParse, EveryFunction) {
  Env env{{"time", 0.3}, {"x", 0.2}, {"y", -0.7}, {"z", 2}};
  EXPECT_NEAR(evaluate(p("sin(x) + cos(y) + tan(x)"), env), std::sin(0.2) + std::cos(-0.7) + std::tan(0.2), 1e-15);
  EXPECT_NEAR(evaluate(p("exp(x) * log(z) - sqrt(z) + abs(y)"), env), std::exp(0.2) * std::log(2) - std::sqrt(2) + 0.7, 1e-15);
  EXPECT_DOUBLE_EQ(evaluate(p("min(x, y) + max(x, y)"), env), -0.5);
  EXPECT_DOUBLE_EQ(evaluate(p("clamp(z, 0, 1)"), env), 1);
  EXPECT_DOUBLE_EQ(evaluate(p("mix(0, 10, time)"), env), 3);
  EXPECT_DOUBLE_EQ(evaluate(p("smoothstep(0, 1, 0.5)"), env), 0.5);
}

TEST(ExprParse, ErrorsPointInsideTheString) {
  Diagnostic d = error_of("8 + sinn(time)");
  EXPECT_EQ(d.loc.line, 4);
  EXPECT_EQ(d.loc.column, 14);  // the string starts at column 10; 'sinn' is at offset 4
  EXPECT_NE(d.message.find("unknown function 'sinn'"), std::string::npos) << d.str();
  EXPECT_EQ(d.hint, "did you mean 'sin'?");

  d = error_of("8 + tme");
  EXPECT_EQ(d.loc.column, 14);
  EXPECT_NE(d.message.find("unknown variable 'tme'"), std::string::npos);
  EXPECT_EQ(d.hint, "did you mean 'time'?");

  d = error_of("x + 1");  // x is not allowed where only time is
  EXPECT_NE(d.message.find("unknown variable 'x'"), std::string::npos);
  EXPECT_NE(d.hint.find("variables here: time"), std::string::npos) << d.hint;

  EXPECT_EQ(error_of("(1 + 2").loc.column, 16);
  EXPECT_NE(error_of("(1 + 2").message.find("missing ')'"), std::string::npos);
  EXPECT_EQ(error_of("1 + * 2").loc.column, 14);
  EXPECT_NE(error_of("1 2").message.find("unexpected '2'"), std::string::npos);
  EXPECT_NE(error_of("max(1)").message.find("max takes 2 arguments, got 1"), std::string::npos);
  EXPECT_NE(error_of("sin").message.find("'sin' is a function"), std::string::npos);
  EXPECT_NE(error_of("").message.find("unexpected end"), std::string::npos);
  EXPECT_NE(error_of("sgn(time)").message.find("unknown function 'sgn'"), std::string::npos);  // internal only
  EXPECT_NE(error_of(std::string(300, '(') + "1" + std::string(300, ')')).message.find("nested deeper"), std::string::npos);
}

TEST(ExprFold, ConstantsFoldAndIdentitiesVanish) {
  EXPECT_EQ(to_string(fold(p("sin(0) + 2 * 3"))), "6");
  EXPECT_EQ(to_string(fold(p("1 * time + 0"))), "time");
  EXPECT_EQ(to_string(fold(p("(2 + 3) * time"))), "(5 * time)");
  EXPECT_TRUE(is_constant(p("sqrt(2) * 3")));
  EXPECT_FALSE(is_constant(p("sqrt(2) * time")));
  EXPECT_TRUE(uses(p("1 + x"), "x"));
  EXPECT_FALSE(uses(p("1 + x"), "y"));
}

TEST(ExprLooks, NumbersAreNotExpressions) {
  EXPECT_FALSE(looks_like_expression("8"));
  EXPECT_FALSE(looks_like_expression("-1.5e3"));
  EXPECT_TRUE(looks_like_expression("8 + sin(time)"));
  EXPECT_TRUE(looks_like_expression("time"));
}

// The interval of an expression holds every sampled value: the property that
// makes it safe for Lipschitz bounds.
TEST(ExprInterval, HoldsEverySample) {
  const char* exprs[] = {"0.05*sin(10*x)*sin(10*y)*sin(10*z)", "x^2 - y^3 + abs(z)", "exp(x) / (2 + cos(y))",
                         "min(x, y) * max(z, 0.5) + clamp(x, -0.2, 0.3)", "mix(x, y, z) + smoothstep(-1, 1, x)",
                         "sqrt(x*x + y*y) - tan(z / 4)", "(x + 2) ^ 1.5 + log(y + 2)"};
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(0, 1);
  for (const char* s : exprs) {
    ExprPtr e = p(s);
    for (int trial = 0; trial < 50; ++trial) {
      IntervalEnv box;
      Env point;
      for (const char* v : {"x", "y", "z"}) {
        double a = -1.5 + 3 * u(rng), w = u(rng);
        box[v] = {a, a + w};
        point[v] = a + w * u(rng);
      }
      Interval r = evaluate_interval(e, box);
      double v = evaluate(e, point);
      EXPECT_LE(r.lo, v + 1e-12) << s;
      EXPECT_GE(r.hi, v - 1e-12) << s;
    }
  }
}

TEST(ExprInterval, TightWhereItMatters) {
  Interval s = evaluate_interval(p("sin(x)"), {{"x", {0, 0.1}}});
  EXPECT_NEAR(s.lo, 0, 1e-15);
  EXPECT_NEAR(s.hi, std::sin(0.1), 1e-15);
  Interval c = evaluate_interval(p("cos(x)"), {{"x", {-0.1, 0.1}}});
  EXPECT_DOUBLE_EQ(c.hi, 1);
  Interval sq = evaluate_interval(p("x^2"), {{"x", {-2, 1}}});
  EXPECT_DOUBLE_EQ(sq.lo, 0);
  EXPECT_DOUBLE_EQ(sq.hi, 4);
}

TEST(ExprDerivative, MatchesFiniteDifferences) {
  const char* exprs[] = {"0.05*sin(10*x)*sin(10*y)*sin(10*z)", "x^3 * y - exp(x * z)", "sqrt(x*x + y*y + 1) / (2 + cos(z))",
                         "mix(x, y*y, z) + smoothstep(-1, 2, x)", "(x + 3) ^ (y + 2)", "log(x + 2) * tan(y / 3)"};
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> u(-0.9, 0.9);
  for (const char* s : exprs) {
    ExprPtr e = p(s);
    for (const char* v : {"x", "y", "z"}) {
      ExprPtr de = derivative(e, v);
      for (int trial = 0; trial < 20; ++trial) {
        Env pt{{"x", u(rng)}, {"y", u(rng)}, {"z", u(rng)}, {"time", 0}};
        double h = 1e-6;
        Env a = pt, b = pt;
        a[v] += h, b[v] -= h;
        double fd = (evaluate(e, a) - evaluate(e, b)) / (2 * h);
        EXPECT_NEAR(evaluate(de, pt), fd, 1e-5 * (1 + std::fabs(fd))) << s << " d/d" << v;
      }
    }
  }
}

TEST(ExprOpenCL, EmitsBuiltinsAndExpandsSmallPowers) {
  auto var = [](std::string_view v) { return std::string(v == "time" ? "frame_time" : "p.x"); };
  auto lit = [](double v) { return std::to_string(v).substr(0, 3) + "f"; };
  EXPECT_EQ(to_opencl(p("abs(x) + time^2"), var, lit), "(fabs(p.x) + (frame_time * frame_time))");
  EXPECT_EQ(to_opencl(p("min(x, 1)"), var, lit), "fmin(p.x, 1.0f)");
  EXPECT_EQ(to_opencl(p("x^0.5"), var, lit), "pow(p.x, 0.5f)");
  EXPECT_EQ(to_opencl(p("x^-2"), var, lit), "(1.0f / (p.x * p.x))");
}

// The flattened tape gives the tree walk's values bit for bit, for every
// root at once, and a variable it is not given throws as the walk does.
TEST(ExprTape, SameValuesAsTheTreeWalk) {
  const char* exprs[] = {"0.05*sin(10*x)*sin(10*y)*sin(10*z)", "x^3 * y - exp(x * z)", "sqrt(x*x + y*y + 1) / (2 + cos(z))",
                         "mix(x, y*y, z) + smoothstep(-1, 2, x)", "(x + 3) ^ (y + 2)", "-log(x + 2) * tan(y / 3) + time"};
  std::vector<ExprPtr> roots;
  for (const char* s : exprs) {
    roots.push_back(p(s));
    roots.push_back(fold(derivative(roots.back(), "x")));
  }
  const Tape tape(roots, {"time", "z", "y", "x"});
  ASSERT_EQ(tape.size(), roots.size());
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(-3, 3);
  for (int trial = 0; trial < 50; ++trial) {
    const double at[4] = {u(rng), u(rng), u(rng), u(rng)};
    std::vector<double> out(roots.size());
    tape.run(at, out.data());
    const Env env{{"time", at[0]}, {"z", at[1]}, {"y", at[2]}, {"x", at[3]}};
    for (size_t k = 0; k < roots.size(); ++k) {
      const double want = evaluate(roots[k], env);
      if (std::isnan(want)) EXPECT_TRUE(std::isnan(out[k])) << to_string(roots[k]);
      else EXPECT_EQ(out[k], want) << to_string(roots[k]);
    }
  }
  const Tape partial({p("x + y")}, {"x"});
  double out = 0;
  const double x = 1;
  EXPECT_THROW(partial.run(&x, &out), std::logic_error);
}

}  // namespace
}  // namespace sdfc::expr
