#pragma once
// Figures of the seakeeping evaluation, after the reference paper (Davis & Holloway 2003): encounter spectra
// (Fig. 7), RAOs vs encounter frequency (Figs. 8–9), rms acceleration per metre of wave height at the three
// passenger positions (Fig. 10), mean MSI vs wave height (Fig. 11) and MSI in the reference sea vs a design
// parameter (Figs. 12–14). Designs are numbered 1..N in list order; panels split by EvaluatedDesign::group.
#include <string>
#include <vector>

#include "io/report/evaluated_design.h"
#include "io/report/svg_plot.h"
#include "seas/wave_spectrum.h"

namespace hullopt::io {

/// Index of the sea used for Figs. 10 and 12–14: the one with the largest Hs (the paper's 3 m sea).
size_t ReferenceSeaIndex(const std::vector<sk::SeaEvaluation>& seas);

/// Fig. 7: S_ζ(ω_e) [m²s/rad] of each sea at speed U in head seas, peak encounter frequencies in the legend.
PlotFigure EncounterSpectraFigure(const std::vector<sk::WaveSpectrum>& spectra, double speed_m_s,
                                  double g_m_s2);
/// Figs. 8–9: heave |x3|/A and pitch |x5|/(kA) vs ω_e; a row of two panels per group.
PlotFigure RaoFigure(const std::vector<EvaluatedDesign>& designs);
/// Fig. 10: rms vertical acceleration per metre of Hs [g/m] at forward, LCG and transom for every design in
/// sea `sea` (x = design number); a panel per group.
PlotFigure AccelerationPerMetreFigure(const std::vector<EvaluatedDesign>& designs, size_t sea);
/// Rms acceleration per metre of Hs [g/m] vs Hs at every position (forward, LCG, transom and the user's
/// points, each named with its x in the legend), a panel per design.
PlotFigure AccelerationPerMetreVsHsFigure(const std::vector<EvaluatedDesign>& designs);
/// MSI [%] along the hull: at every position (named beside its marker) against its x from the CG [m], a line
/// per sea, a panel per design.
PlotFigure MsiAlongHullFigure(const std::vector<EvaluatedDesign>& designs);
/// Fig. 11: mean MSI [%] vs Hs, a line per design, a panel per group.
PlotFigure MsiVsHsFigure(const std::vector<EvaluatedDesign>& designs);
/// Figs. 12–14: mean MSI [%] in sea `sea` vs designs[i].parameters[parameter]; designs without the parameter
/// are left out. Point labels are the design numbers.
PlotFigure MsiVsParameterFigure(const std::vector<EvaluatedDesign>& designs, const std::string& parameter,
                                const std::string& axis_label, size_t sea);

}  // namespace hullopt::io
