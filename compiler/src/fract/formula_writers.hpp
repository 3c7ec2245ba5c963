#pragma once
// The writers behind the formula table's rows, and the helpers they share.
// Internal to the importer.
#include <string>

#include "formula_table.hpp"

namespace sdfc::fract {

// "[fractal_N] KEY": where a value came from.
std::string from(const FormulaInput& in, const std::string& key);
// `iterations: N`, capped at `cap` (the comment says so).
Field iterations_field(const FormulaInput& in, int cap);
// Refuses dont_add_c_constant_N and a fractal_constant_factor other than 1.
void require_c_added(const FormulaInput& in);

// formula_chains.cpp: Mandelbulber's rotation angles (degrees) as rotate
// steps ("" or items ending in ", "); the step adding c (times
// fractal_constant_factor; "" when `adds` is false); whether the formula adds
// c (dont_add_c_constant_N against its default); julia_c times the factor.
std::string rotation_steps(const Vec3& degrees, bool mirror);
std::string add_c_step(const FormulaInput& in, bool adds);
bool adds_c(const FormulaInput& in, bool by_default);
Vec3 julia_constant(const FormulaInput& in);
// One formula alone as a `formula:` node of its chain.
Node chain_formula(const FormulaInput& in, const ChainPart& part);

ChainPart mandelbulb_chain(const FormulaInput& in);         // id 2, formula_bulbs.cpp
ChainPart mandelbulb_power2_chain(const FormulaInput& in);  // id 3
ChainPart mandelbox_chain(const FormulaInput& in);          // id 8, formula_chains.cpp
ChainPart menger_chain(const FormulaInput& in);             // id 7
ChainPart ifs_chain(const FormulaInput& in);                // id 10
Node mandelbulb(const FormulaInput& in);
Node mandelbulb_power2(const FormulaInput& in);
Node ifs(const FormulaInput& in);
Node xenodreambuie(const FormulaInput& in);  // id 11, formula_presets.cpp
Node menger_mod1(const FormulaInput& in);    // id 61
Node quaternion_mandelbrot(const FormulaInput& in);  // id 5 without julia mode
Node hypercomplex(const FormulaInput& in);           // id 4
Node aexion(const FormulaInput& in);                 // id 19

}  // namespace sdfc::fract
