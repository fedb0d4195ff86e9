package sitcov.seam;

/** The right-of-way signal is stuck at "would grant": every junction shows it would be given to the car if asked. */
final class AlwaysGranted extends ObservationView {
    @Override
    int parts() {
        return Part.RIGHT_OF_WAY;
    }

    @Override
    public boolean wouldGrant(int junction) {
        return junction >= 0 && junction < real.roads().junctions().size() || real.rightOfWay().wouldGrant(junction);
    }
}
