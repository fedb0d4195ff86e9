/**
 * Seam faults: sensor and actuator faults that act on any controller, at the seam where it meets the
 * world (faults/README.md, "Seam faults"). Each {@link sitcov.seam.SeamFault} of the catalogue is a
 * deterministic transformation of the observation a controller is handed or of the command it gives,
 * its randomness drawn from a named stream of the run. {@link sitcov.seam.SeamControllers} wraps a
 * reference controller's factory: its controllers are the reference's, handed the transformed
 * observation and giving the transformed command ({@link sitcov.seam.SeamController}), or, watching
 * faults from the shadows, the reference's own values together with the tick each fault would first
 * have changed one ({@link sitcov.seam.SeamBoard}). Depends on the controller seam, the engine's
 * random streams, the sensors' ranges and the geometry only. Its classes keep no final instance
 * fields: a checkpoint of a run copies them field by field ({@link sitcov.engine.ModelCopy}).
 */
package sitcov.seam;
