// The sections of the report: one listing every run, one per experiment command (built from its
// runs, registered by command name in one table: adding an experiment is adding a row), and a
// plain headline section for any other command found in a run directory.
#pragma once

#include <functional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "report/document.hpp"
#include "report/run_directory.hpp"

namespace rbcsim::report {

using RunList = std::vector<const RunDirectory*>;

struct ExperimentSection {
  std::string_view command;
  Section (*build)(const RunList& runs);  // runs of this command, in report order
};

// calibrate, stretch, shear, capillary, suspension, sheared_suspension: the order of the report.
std::span<const ExperimentSection> experiment_sections();

Section build_runs_section(const RunList& runs);
// The comparisons of every experiment's runs with the paper and the reference data, from the
// runs and the experiment sections already built (their summaries).
Section build_verdict_section(const RunList& runs, const std::vector<Section>& sections);
Section build_calibrate_section(const RunList& runs);
Section build_stretch_section(const RunList& runs);
Section build_shear_section(const RunList& runs);
Section build_capillary_section(const RunList& runs);
Section build_suspension_section(const RunList& runs);
Section build_sheared_suspension_section(const RunList& runs);
// Runs of a command without a section of its own: their headline numbers.
Section build_other_section(const std::string& command, std::size_t index, const RunList& runs);

// ---- Parts the section builders share.

// describe(run) for every run, with the run directory appended to the labels that would
// otherwise be shared by two runs, so every series and row of a section is told apart.
std::vector<std::string> distinct_labels(
    const RunList& runs, const std::function<std::string(const RunDirectory&)>& describe);

// The distinct values of a property (a member such as &RunDirectory::terms, or a function of the
// run) over the runs, in order of appearance.
std::vector<std::string> distinct(const RunList& runs,
                                  const std::function<std::string(const RunDirectory&)>& value_of);

// "discocyte, all six".
std::string morphology_and_terms(const RunDirectory& run);

// {"directory", "morphology", "terms", "forces"}: how summary.json names a run.
nlohmann::json run_identity(const RunDirectory& run);

// run_identity plus the command's own object of result.json ("stretch": {...}): a run's entry
// in its section of summary.json.
nlohmann::json run_summary(const RunDirectory& run);

// The runs `plotted` accepts: by default those whose status is "ok". Any other run (failed or
// interrupted) is listed in the runs section and, here, named in a paragraph of `section`: its
// numbers are not results, so they are not plotted.
RunList plotted_runs(
    const RunList& runs, Section& section,
    const std::function<bool(const RunDirectory&)>& plotted = &RunDirectory::succeeded);

// A run that stopped (failed or interrupted) but whose partial record is worth drawing: its plot
// label carries its status ("discocyte, all six (failed)"), it is named in a paragraph of
// `section` saying how the plots show it, and it is left out of everything else.
std::string label_with_status(const RunDirectory& run, const std::string& label);
// Whether a run is worth drawing: it finished, or an entry of the `member` array of its command's
// object (a shear rate, a stretch force) is a result by `is_result`. Read leniently: a stopped
// run's object may be partial.
bool has_result_entries(const RunDirectory& run, const std::string& member,
                        const std::function<bool(const nlohmann::json&)>& is_result);
void name_unfinished_runs(const RunList& runs, const std::string& how_drawn, Section& section);

// Each run's result.json "headline" object as a table row.
Table headline_table(const RunList& runs, const std::vector<std::string>& labels);

}  // namespace rbcsim::report
