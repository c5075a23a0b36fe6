#pragma once
// The experiments behind runExperiment (experiment.h), one file each. Internal to the lab
// library: each writes its files through the context and appends its summary.

namespace prt {

class ExperimentContext;

void runTable3(ExperimentContext& cx);          // table3.cpp
void runSpeedIndex(ExperimentContext& cx);      // speed_index_experiment.cpp
void runInitialPercent(ExperimentContext& cx);  // initial_percent.cpp
void runCompare(ExperimentContext& cx);         // compare.cpp
void runScale(ExperimentContext& cx);           // scale.cpp
void runJoins(ExperimentContext& cx);           // joins.cpp
void runFaults(ExperimentContext& cx);          // faults.cpp

}  // namespace prt
