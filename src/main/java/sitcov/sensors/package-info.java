/**
 * What the world offers every controller to sense with: the standard road-marking
 * {@link sitcov.sensors.MarkingCamera} (its rays, its {@link sitcov.sensors.CameraSettings} and the
 * {@link sitcov.sensors.LaneEstimate} it gives), the {@link sitcov.sensors.Lidar} sweep, and the
 * processing of radar tracks ({@link sitcov.sensors.TrafficSensor}). Each works on the road map and
 * on what an observation reports, never on the scene, so the world's observation and a controller's
 * own processing (the builtin car's, a degraded camera under a fault) use the same code. Nothing
 * allocates per tick; nothing keeps a final instance field, as a checkpoint copies it field by field.
 */
package sitcov.sensors;
