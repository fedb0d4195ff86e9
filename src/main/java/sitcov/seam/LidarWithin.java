package sitcov.seam;

/** The LIDAR sweep's raw hits beyond a shorter range of the car's front are lost. */
final class LidarWithin extends ObservationView {
    private double range;
    private int[] kept = new int[64];
    private int keptCount;
    private long keptAt = -1;

    LidarWithin(double range) {
        this.range = range;
    }

    @Override
    int parts() {
        return Part.LIDAR;
    }

    private void keep() {
        if (keptAt == tick) {
            return;
        }
        keptCount = 0;
        double x = real.x();
        double y = real.y();
        for (int i = 0, n = real.lidarHits(); i < n; i++) {
            if (Math.hypot(real.lidarHitX(i) - x, real.lidarHitY(i) - y) <= range) {
                if (keptCount == kept.length) {
                    kept = java.util.Arrays.copyOf(kept, 2 * keptCount);
                }
                kept[keptCount++] = i;
            }
        }
        keptAt = tick;
    }

    @Override
    public int lidarHits() {
        keep();
        return keptCount;
    }

    @Override
    public double lidarHitX(int hit) {
        keep();
        return real.lidarHitX(kept[hit]);
    }

    @Override
    public double lidarHitY(int hit) {
        keep();
        return real.lidarHitY(kept[hit]);
    }
}
