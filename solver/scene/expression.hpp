// Arithmetic expressions in scene files, so that one parameter (a resolution, a Womersley number)
// can drive every number that depends on it: "4 * dp_fluid", "2 * pi / period", "sqrt(K / rho)".
// Grammar: numbers, parameter names, + - * / ^, parentheses, unary minus, and the functions
// sqrt, sin, cos, exp, log, abs, min(a, b), max(a, b). The constant pi is predefined.
#pragma once

#include <map>
#include <stdexcept>
#include <string>

namespace mrsph {

class ExpressionError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

using ParameterTable = std::map<std::string, double>;

// Throws ExpressionError naming the problem (unknown name, syntax error, position).
double evaluate_expression(const std::string& text, const ParameterTable& parameters);

}  // namespace mrsph
