package sitcov.export;

import static org.junit.jupiter.api.Assertions.fail;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import java.io.IOException;
import java.io.StringReader;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.EnumMap;
import java.util.List;
import java.util.Map;
import javax.xml.XMLConstants;
import javax.xml.transform.stream.StreamSource;
import javax.xml.validation.Schema;
import javax.xml.validation.SchemaFactory;
import javax.xml.validation.Validator;
import org.xml.sax.ErrorHandler;
import org.xml.sax.SAXException;
import org.xml.sax.SAXParseException;

/**
 * The ASAM schemas the export is checked against: OpenDRIVE 1.7 and OpenSCENARIO 1.0–1.3, as the
 * pinned scenariogeneration wheel ships them, fetched by .ci/fetch-asam-schemas (which .ci/run calls) into target/asam-schemas/. Missing
 * schemas skip the tests that need them, except under CI=true, where they fail naming the fetch
 * (src/main/java/sitcov/export/README.md, "Export to OpenDRIVE and OpenSCENARIO"). Public for the export command's
 * tests.
 */
public final class AsamSchemas {
    static final Path DIR = Path.of("target", "asam-schemas");
    static final String FETCH = "bash .ci/fetch-asam-schemas (from the repository root; it needs python3 and PyPI)";
    private static final int ERRORS_SHOWN = 5;

    private static Schema openDrive;
    private static final Map<ScenarioVersion, Schema> OPEN_SCENARIO = new EnumMap<>(ScenarioVersion.class);

    private AsamSchemas() {
    }

    /** OpenDRIVE 1.7: its core file includes the other six, so it is loaded by its path for them to resolve. */
    public static synchronized Schema openDrive() {
        if (openDrive == null) {
            openDrive = load("opendrive_17_core.xsd");
        }
        return openDrive;
    }

    public static synchronized Schema openScenario(ScenarioVersion version) {
        return OPEN_SCENARIO.computeIfAbsent(version, v -> load(name(v)));
    }

    /** The schema file of {@code version}, present (the test is skipped, or fails on CI, when it is not). */
    static Path file(ScenarioVersion version) {
        openScenario(version);
        return DIR.resolve(name(version)).toAbsolutePath();
    }

    private static String name(ScenarioVersion version) {
        return switch (version) {
            case V1_0 -> "OpenSCENARIO_1_0.xsd";
            case V1_1 -> "OpenSCENARIO_1_1.xsd";
            case V1_2 -> "OpenSCENARIO_1_2.xsd";
            case V1_3 -> "OpenSCENARIO_1_3_1.xsd";
        };
    }

    /** Fails, naming {@code what} and the first few errors with their line and column, unless {@code xml} is valid. */
    public static void assertValid(Schema schema, String xml, String what) {
        List<String> errors = errors(schema, xml);
        if (!errors.isEmpty()) {
            String more = errors.size() > ERRORS_SHOWN ? "\n  …" : "";
            fail(what + " breaks its schema:\n  "
                    + String.join("\n  ", errors.subList(0, Math.min(errors.size(), ERRORS_SHOWN))) + more);
        }
    }

    /** The schema errors of {@code xml}, each as line:column: message, one more than {@link #ERRORS_SHOWN} at most. */
    static List<String> errors(Schema schema, String xml) {
        List<String> errors = new ArrayList<>();
        Validator validator = schema.newValidator();
        validator.setErrorHandler(new ErrorHandler() {
            @Override
            public void warning(SAXParseException e) {
            }

            @Override
            public void error(SAXParseException e) throws SAXException {
                errors.add("line " + e.getLineNumber() + ":" + e.getColumnNumber() + ": " + e.getMessage());
                if (errors.size() > ERRORS_SHOWN) {
                    throw e; // enough to act on; the rest usually repeat the first
                }
            }

            @Override
            public void fatalError(SAXParseException e) throws SAXException {
                error(e);
                throw e;
            }
        });
        try {
            validator.validate(new StreamSource(new StringReader(xml)));
        } catch (SAXException e) {
            if (errors.isEmpty()) {
                errors.add(e.getMessage());
            }
        } catch (IOException e) {
            throw new AssertionError("could not read a document held in memory", e);
        }
        return errors;
    }

    private static Schema load(String file) {
        Path path = DIR.resolve(file).toAbsolutePath().normalize();
        boolean present = Files.isRegularFile(path);
        if (!present && "true".equals(System.getenv("CI"))) {
            fail(path + " is missing on CI: fetch the ASAM schemas first: " + FETCH);
        }
        assumeTrue(present, path + " is missing, so the export is not checked against the ASAM schemas;"
                + " fetch them with: " + FETCH);
        try {
            SchemaFactory factory = SchemaFactory.newInstance(XMLConstants.W3C_XML_SCHEMA_NS_URI);
            // read from the file itself (its URI is the systemId), so relative xs:include locations resolve beside it
            return factory.newSchema(new StreamSource(path.toFile()));
        } catch (SAXException e) {
            throw new AssertionError("the schema " + path + " does not load: " + e.getMessage(), e);
        }
    }
}
