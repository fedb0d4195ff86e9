/**
 * The seam between the world and the controller under test (experiments/controllers/README.md, "Testing your own
 * controller").
 * Each tick the world hands a {@link sitcov.control.Controller} an {@link sitcov.control.Observation}
 * (its sensors, its navigation knowledge, the right-of-way signals and any ground-truth channels it
 * asked for) and takes back a {@link sitcov.control.Command} (a speed change and a steering angle,
 * clamped to the car's limits, plus right-of-way requests). The world owns the body and the
 * physics; no controller sees or changes the scene.
 */
package sitcov.control;
