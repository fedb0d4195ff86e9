package sitcov.report;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import sitcov.control.ControllerFactory;
import sitcov.experiment.CampaignTarget;
import sitcov.results.CampaignManifest;
import sitcov.results.FolderLock;

/**
 * Combines the folders of shards 1/N … N/N of one campaign into the folder the unsharded campaign would have
 * written (experiments/README.md, "Campaigns: falsifying one version"): each target's sub-folders merged as the
 * suites' shards are ({@link ShardMerger}), then the campaign's own files written from them.
 */
public final class CampaignMerger {
    private CampaignMerger() {
    }

    /**
     * @throws IllegalArgumentException naming the folder and what is wrong with it, or when {@code out} holds files
     * @throws IllegalStateException when another run or merge is writing into {@code out}
     */
    public static void merge(List<Path> shards, Path out, Map<String, String> execution, ControllerFactory builtin)
            throws IOException {
        List<CampaignManifest> manifests = new ArrayList<>();
        for (Path shard : shards) {
            if (!CampaignManifest.isCampaign(shard)) {
                throw new IllegalArgumentException(shard + " is not a shard of a campaign (it has no "
                        + CampaignManifest.FILE + "), unlike " + shards.get(0) + ": merge the shards of one campaign");
            }
            manifests.add(CampaignManifest.read(shard));
        }
        CampaignManifest first = manifests.get(0);
        int n = first.shard().n();
        boolean[] seen = new boolean[n + 1];
        for (int i = 0; i < shards.size(); i++) {
            CampaignManifest m = manifests.get(i);
            Path folder = shards.get(i);
            if (!m.sameCampaign(first)) {
                throw new IllegalArgumentException(folder + " is not a shard of the same campaign as " + shards.get(0)
                        + " (their " + CampaignManifest.FILE + " differ)");
            }
            if (m.shard().isWhole() || m.shard().n() != n) {
                throw new IllegalArgumentException(folder + " holds " + (m.shard().isWhole() ? "a whole campaign" : "shard "
                        + m.shard()) + " but " + shards.get(0) + " is shard " + first.shard() + ": merge the shards of one split");
            }
            if (!m.complete()) {
                throw new IllegalArgumentException(folder + " (shard " + m.shard() + ") is not complete; finish it with"
                        + " run --resume " + folder);
            }
            if (seen[m.shard().k()]) {
                throw new IllegalArgumentException("shard " + m.shard() + " is given twice");
            }
            seen[m.shard().k()] = true;
        }
        if (shards.size() != n) {
            throw new IllegalArgumentException("merge needs all " + n + " shards of the campaign, got " + shards.size());
        }
        CampaignManifest merged = first.whole().complete(false);
        Files.createDirectories(out);
        try (FolderLock lock = FolderLock.claim(out)) {
            ShardMerger.requireEmpty(out);
            merged.write(out);
            for (CampaignTarget t : merged.config().targets()) {
                ShardMerger.merge(shards.stream().map(s -> s.resolve(t.folder())).toList(), out.resolve(t.folder()),
                        execution, builtin);
            }
            CampaignFinisher.finish(out, merged);
        }
    }
}
