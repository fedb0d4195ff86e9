/**
 * Vehicles. The world's side: the car under test ({@link sitcov.vehicles.AutonomousCar}, a body the
 * world moves on its controller's commands, judging arrival from geometry), its observation (built
 * from the scene each tick with the standard sensors of {@link sitcov.sensors}, and the junctions'
 * right-of-way), the moving cars that drive by ground truth, the junction locks, the
 * {@link sitcov.vehicles.Scene} they share and the run's {@link sitcov.vehicles.Telemetry}, all that
 * watchers of a run receive. What every car shares lives here too: bodies and their
 * {@link sitcov.vehicles.Dynamics}, lane geometry, the path through a junction and the distances
 * kept there. No controller is named: the controller comes from the factory a run is given. What a
 * run holds keeps no final instance fields: a checkpoint copies it field by field
 * ({@link sitcov.engine.ModelCopy}).
 */
package sitcov.vehicles;
