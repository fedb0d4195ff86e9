/**
 * The seeded faults: the {@link sitcov.faults.Fault} catalogue, fault sets, and the per-run
 * {@link sitcov.faults.FaultSwitchboard} a controller with seeded faults consults, which records
 * each fault's activation. A controller with seeded faults has a
 * {@link sitcov.faults.SeededControllerFactory}: whoever runs it hands it the run's switchboard
 * (any other controller is started without one), and {@link sitcov.faults.PlantedFaults} is a
 * version of it with faults always on. Depends on the engine and the controller seam only. The
 * switchboard keeps no final instance fields: a checkpoint copies it field by field
 * ({@link sitcov.engine.ModelCopy}).
 */
package sitcov.faults;
