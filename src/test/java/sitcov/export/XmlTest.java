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
    void aOneLineBlockStartsAtTheMarginWithNoBreaksInside() {
        String doc = new Xml().open("r").open("s").startLine().open("v", "t", "1").empty("p").close().endLine().close()
                .close().document();
        assertEquals("<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<r>\n  <s>\n<v t=\"1\"><p/></v>\n  </s>\n</r>\n", doc);
    }

    @Test
    void aDecimalIsWrittenExactlyWithoutTrailingZeros() {
        assertEquals("34.913", Xml.decimal(34913, 3));
        assertEquals("34.013", Xml.decimal(34013, 3));
        assertEquals("-0.6", Xml.decimal(-600, 3));
        assertEquals("-0.006", Xml.decimal(-6, 3));
        assertEquals("0", Xml.decimal(0, 3));
        assertEquals("108", Xml.decimal(1080, 1));
        assertEquals("-3.1415", Xml.decimal(-31415, 4));
    }

    @Test
    void aDocumentWithAnElementLeftOpenIsRefused() {
        assertThrows(IllegalStateException.class, () -> new Xml().open("r").document());
    }
}
