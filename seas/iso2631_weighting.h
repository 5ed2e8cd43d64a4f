#pragma once
// ISO 2631-1:1997 frequency weighting W_f for motion sickness (vertical acceleration, 0.1–0.5 Hz band).
// Parameters (ISO 2631-1:1997 Annex A, from secondary summaries; docs/evaluate.md, 'Method'): band limits
// f1 = 0.08 Hz (high pass, Q = 1/√2), f2 = 0.63 Hz (low pass), a–v transition f3 = ∞, f4 = 0.25 Hz,
// Q4 = 0.86, upward step f5 = 0.0625 Hz, Q5 = 0.80, f6 = 0.10 Hz, Q6 = 0.80. The upward step is used without
// a (f6/f5)² gain, so |W_f| ≈ 1 at 0.16–0.2 Hz (as in public implementations); not checked against the
// printed ISO table.
namespace hullopt::sk {

/// |W_f(f)| [-] at frequency f [Hz] (f > 0).
double Iso2631WfMagnitude(double f_hz);

}  // namespace hullopt::sk
