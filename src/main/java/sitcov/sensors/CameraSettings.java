package sitcov.sensors;

/**
 * What the road-marking camera can see (faults/README.md, "The car under test, the traffic and the oracle"):
 * the arc to the left and right of the
 * lane direction (the kerb-side edge line is looked for on the left, the centre line on the
 * right), its range, and how finely it samples angle and distance. These are what faults 8–13 degrade.
 *
 * @param leftArc     degrees of arc searched on the left (kerb side)
 * @param rightArc    degrees of arc searched on the right (centre side)
 * @param range       metres; samples reach one range step beyond it, as in the original
 * @param angularStep degrees between rays
 * @param rangeStep   metres between samples along a ray
 * @param rangeStart  metres along the ray before the first sample step
 */
public record CameraSettings(double leftArc, double rightArc, double range, double angularStep,
                             double rangeStep, double rangeStart) {
    /** 90° (45° each side), 10 m, 0.5°, 0.5 m. */
    public static final CameraSettings STANDARD = new CameraSettings(45, 45, 10, 0.5, 0.5, 0);

    /** The farthest sample distance. */
    public double limit() {
        int samples = (int) Math.floor((range - rangeStart) / rangeStep + 1e-9) + 1;
        return rangeStart + samples * rangeStep;
    }
}
