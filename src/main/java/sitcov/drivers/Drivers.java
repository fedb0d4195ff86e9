package sitcov.drivers;

import java.util.Collections;
import java.util.LinkedHashMap;
import java.util.Map;
import java.util.Set;
import java.util.function.Supplier;
import sitcov.experiment.Driver;
import sitcov.experiment.DriverFactory;

/** The drivers a preset can name ({@code drivers=coverage-filter,random}), each made fresh per replication. */
public final class Drivers implements DriverFactory {
    private final Map<String, Supplier<Driver>> byName;

    private Drivers(Map<String, Supplier<Driver>> byName) {
        this.byName = Collections.unmodifiableMap(new LinkedHashMap<>(byName));
    }

    /** The drivers sitcov ships. A new driver needs one line here and nothing else. */
    public static Drivers standard() {
        Map<String, Supplier<Driver>> m = new LinkedHashMap<>();
        m.put("coverage-filter", CoverageFilterDriver::new);
        m.put("random", RandomDriver::new);
        m.put("every-other", EveryOtherDriver::new);
        m.put("coverage-search", CoverageSearchDriver::new);
        m.put("fault-search", CoverageSearchDriver::faultSearch);
        m.put("stress-search", StressSearchDriver::new);
        return new Drivers(m);
    }

    /** These drivers and one more (for experiments built in code). */
    public Drivers with(String name, Supplier<Driver> driver) {
        Map<String, Supplier<Driver>> m = new LinkedHashMap<>(byName);
        if (m.putIfAbsent(name, driver) != null) {
            throw new IllegalArgumentException("a driver named '" + name + "' exists already");
        }
        return new Drivers(m);
    }

    public Set<String> names() {
        return byName.keySet();
    }

    public boolean has(String name) {
        return byName.containsKey(name);
    }

    @Override
    public Driver create(String name) {
        Supplier<Driver> s = byName.get(name);
        if (s == null) {
            throw new IllegalArgumentException("unknown driver '" + name + "'; the drivers are " + String.join(", ", names()));
        }
        return s.get();
    }
}
