package sitcov.judge;

import sitcov.stats.Wilson;

/** A share of successes among trials, with its 95% Wilson score interval. */
public record Proportion(long successes, long trials) {
    public Proportion {
        if (trials < 0 || successes < 0 || successes > trials) {
            throw new IllegalArgumentException("a proportion needs 0 <= successes <= trials, got " + successes + "/" + trials);
        }
    }

    public double share() {
        return trials == 0 ? 0 : (double) successes / trials;
    }

    public double wilsonLow() {
        return Wilson.interval(successes, trials).low();
    }

    public double wilsonHigh() {
        return Wilson.interval(successes, trials).high();
    }
}
