package sitcov.seam;

import sitcov.control.Channel;

/** A ground-truth channel reads a fixed amount off its true value (NaN, where it has none, stays NaN). */
final class ChannelBias extends ObservationView {
    private Channel biased;
    private double by;

    ChannelBias(Channel biased, double by) {
        this.biased = biased;
        this.by = by;
    }

    @Override
    int parts() {
        return Part.channel(biased);
    }

    @Override
    public double channel(Channel channel) {
        return channel == biased ? real.channel(channel) + by : real.channel(channel);
    }
}
