package sitcov.estimate;

import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import sitcov.world.DrawSite;

/** proposals.csv: per replication and stage, the proposal its maps were drawn under (bin probabilities, 6 decimals). */
public final class ProposalTable {
    private ProposalTable() {
    }

    public static String header() {
        List<String> h = new ArrayList<>(List.of("replication", "stage", "elite_level", "elite_runs"));
        for (DrawSite s : DrawSite.values()) {
            h.add("p_" + s.key());
        }
        return String.join(",", h);
    }

    public static String row(ProposalRow p) {
        StringBuilder b = new StringBuilder().append(p.replication()).append(',').append(p.stage()).append(',')
                .append(Double.isNaN(p.level()) ? "" : String.format(Locale.ROOT, "%.4f", p.level())).append(',')
                .append(p.elite());
        for (DrawSite s : DrawSite.values()) {
            b.append(',');
            for (int bin = 0; bin < s.bins(); bin++) {
                b.append(bin == 0 ? "" : " ").append(String.format(Locale.ROOT, "%.6f", p.tilt().probability(s, bin)));
            }
        }
        return b.toString();
    }
}
