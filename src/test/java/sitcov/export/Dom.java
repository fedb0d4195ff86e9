package sitcov.export;

import java.io.IOException;
import java.io.StringReader;
import java.util.ArrayList;
import java.util.List;
import java.util.Optional;
import javax.xml.XMLConstants;
import javax.xml.parsers.DocumentBuilderFactory;
import javax.xml.parsers.ParserConfigurationException;
import org.w3c.dom.Document;
import org.w3c.dom.Element;
import org.w3c.dom.Node;
import org.w3c.dom.NodeList;
import org.xml.sax.InputSource;
import org.xml.sax.SAXException;

/** Reading an exported document with the JDK's DOM parser, failing with the element's name when something is missing. */
final class Dom {
    private Dom() {
    }

    static Element parse(String xml) {
        return parse(xml, false);
    }

    /** A document whose elements know their namespace, as a schema's do. */
    static Element parseNamespaced(String xml) {
        return parse(xml, true);
    }

    private static Element parse(String xml, boolean namespaces) {
        try {
            DocumentBuilderFactory factory = DocumentBuilderFactory.newInstance();
            factory.setNamespaceAware(namespaces);
            factory.setFeature(XMLConstants.FEATURE_SECURE_PROCESSING, true);
            factory.setFeature("http://apache.org/xml/features/disallow-doctype-decl", true);
            Document doc = factory.newDocumentBuilder().parse(new InputSource(new StringReader(xml)));
            return doc.getDocumentElement();
        } catch (ParserConfigurationException | SAXException | IOException e) {
            throw new AssertionError("the export is not well-formed XML: " + e.getMessage(), e);
        }
    }

    /** The element children of {@code parent} named {@code tag}, in document order. */
    static List<Element> children(Element parent, String tag) {
        List<Element> out = new ArrayList<>();
        for (Node n = parent.getFirstChild(); n != null; n = n.getNextSibling()) {
            if (n instanceof Element e && e.getTagName().equals(tag)) {
                out.add(e);
            }
        }
        return out;
    }

    static Optional<Element> optionalChild(Element parent, String tag) {
        List<Element> found = children(parent, tag);
        if (found.size() > 1) {
            throw new AssertionError(describe(parent) + " has " + found.size() + " <" + tag + "> children, expected at most one");
        }
        return found.stream().findFirst();
    }

    static Element child(Element parent, String tag) {
        return optionalChild(parent, tag)
                .orElseThrow(() -> new AssertionError(describe(parent) + " has no <" + tag + "> child"));
    }

    /** Every element below {@code root} named {@code tag}, at any depth, in document order. */
    static List<Element> descendants(Element root, String tag) {
        NodeList list = root.getElementsByTagName(tag);
        List<Element> out = new ArrayList<>(list.getLength());
        for (int i = 0; i < list.getLength(); i++) {
            out.add((Element) list.item(i));
        }
        return out;
    }

    /** The nearest ancestor of {@code e} named {@code tag}, if any. */
    static Optional<Element> ancestor(Element e, String tag) {
        for (Node n = e.getParentNode(); n instanceof Element a; n = a.getParentNode()) {
            if (a.getTagName().equals(tag)) {
                return Optional.of(a);
            }
        }
        return Optional.empty();
    }

    static String text(Element e, String attribute) {
        if (!e.hasAttribute(attribute)) {
            throw new AssertionError(describe(e) + " has no attribute " + attribute);
        }
        return e.getAttribute(attribute);
    }

    static double number(Element e, String attribute) {
        String v = text(e, attribute);
        try {
            return Double.parseDouble(v);
        } catch (NumberFormatException ex) {
            throw new AssertionError(describe(e) + " has " + attribute + "=\"" + v + "\", not a number");
        }
    }

    static double number(Element e, String attribute, double absent) {
        return e.hasAttribute(attribute) ? number(e, attribute) : absent;
    }

    static String describe(Element e) {
        String id = e.hasAttribute("id") ? " id=\"" + e.getAttribute("id") + "\""
                : e.hasAttribute("name") ? " name=\"" + e.getAttribute("name") + "\"" : "";
        return "<" + e.getTagName() + id + ">";
    }
}
