/**
 * Situations and recorded runs in the ASAM formats any simulator plays (src/main/java/sitcov/export/README.md,
 * "Export to OpenDRIVE and OpenSCENARIO"): {@link sitcov.export.OpenDrive} writes a map's roads, lanes and
 * T-junctions; {@link sitcov.export.OpenScenario} writes what stands and moves on them, either the
 * situation at its start, the car under test given its route ({@code EgoRoute}), or a
 * {@link sitcov.export.RunRecording} as timed trajectories with its accidents and contacts declared as the events
 * a player reports them by ({@code Declared}); {@link sitcov.export.AsamFrame} holds the one mapping between
 * sitcov's coordinates and theirs. Documents are strings built in memory, the same bytes for the same map,
 * seeds and faults.
 */
package sitcov.export;
