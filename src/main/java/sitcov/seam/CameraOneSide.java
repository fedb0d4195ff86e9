package sitcov.seam;

import sitcov.geom.Bearing;

/**
 * The road-marking camera goes blind on the driver's right: its hits to the right of the car's
 * heading are lost. Driving on the left, that is the side of the centre line.
 */
final class CameraOneSide extends ObservationView {
    private int[] kept = new int[64];
    private int keptCount;
    private long keptAt = -1;

    @Override
    int parts() {
        return Part.CAMERA;
    }

    private void keep() {
        if (keptAt == tick) {
            return;
        }
        keptCount = 0;
        double h = real.heading();
        // the unit vector to the driver's right: steering > 0 turns to larger bearings, the left
        double rx = Bearing.dx(h - 90);
        double ry = Bearing.dy(h - 90);
        double x = real.x();
        double y = real.y();
        for (int i = 0, n = real.cameraHits(); i < n; i++) {
            if ((real.cameraHitX(i) - x) * rx + (real.cameraHitY(i) - y) * ry <= 0) {
                if (keptCount == kept.length) {
                    kept = java.util.Arrays.copyOf(kept, 2 * keptCount);
                }
                kept[keptCount++] = i;
            }
        }
        keptAt = tick;
    }

    @Override
    public int cameraHits() {
        keep();
        return keptCount;
    }

    @Override
    public double cameraHitX(int hit) {
        keep();
        return real.cameraHitX(kept[hit]);
    }

    @Override
    public double cameraHitY(int hit) {
        keep();
        return real.cameraHitY(kept[hit]);
    }
}
