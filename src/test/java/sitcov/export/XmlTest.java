package sitcov.export;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;

import org.junit.jupiter.api.Test;

class XmlTest {

    @Test
    void attributeTextIsEscaped() {
        String doc = new Xml().empty("a", "name", "<\"fast\" & loose>").document();
        assertEquals("<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<a name=\"&lt;&quot;fast&quot; &amp; loose&gt;\"/>\n", doc);
    }

    @Test
    void aNegativeZeroIsWrittenAsZeroSoTheSameValueAlwaysReadsTheSame() {
        assertEquals("0.0000", Xml.metres(-0.00001));
        assertEquals("-0.0001", Xml.metres(-0.0001));
        assertEquals("12.3", Xml.seconds(12.3));
    }

    @Test
    void aOneLineBlockHasNoBreaksInside() {
        String doc = new Xml().open("r").startLine().open("v", "t", "1").empty("p").close().endLine().close().document();
        assertEquals("<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<r>\n  <v t=\"1\"><p/></v>\n</r>\n", doc);
    }

    @Test
    void aDocumentWithAnElementLeftOpenIsRefused() {
        assertThrows(IllegalStateException.class, () -> new Xml().open("r").document());
    }
}
