#pragma once

namespace aapat {

// sin, cos, exp, log and pow that give the same bits on every platform aapat
// builds for. The C libraries round a few results differently in the last bit
// (glibc's and musl's, which the WebAssembly build uses, have different sin and
// cos), and a last bit can decide an optimizer's branch, so a seeded search
// ended in another local minimum in the page than in the CLI. These evaluate
// in double-double arithmetic (about 106 bits, with the basic operations only,
// which IEEE 754 rounds the same everywhere) and round once, so they are also
// correctly rounded but for results within about 2^-100 of a tie.
//
// They cost tens to hundreds of nanoseconds: for tables and per-step
// decisions, not for inner loops. Arguments of sin and cos are reduced with a
// three-part pi/2, exact for |x| < 2^20; beyond that the result is still the
// same everywhere, only less accurate.
double portable_sin(double x);
double portable_cos(double x);
double portable_exp(double x);
double portable_log(double x);
// x^y for x > 0 (exp(y log x) in double-double), 1 for y == 0, NaN for x < 0
// with y not an integer; x == 0 gives 0 for y > 0 and infinity for y < 0.
double portable_pow(double x, double y);

// exp and log for a loop's every step (the annealer's acceptance, a normal
// draw): plain double arithmetic, so the same bits everywhere, within about
// two units in the last place, at a few nanoseconds instead of hundreds.
double portable_exp_fast(double x);
double portable_log_fast(double x);  // x > 0

}  // namespace aapat
