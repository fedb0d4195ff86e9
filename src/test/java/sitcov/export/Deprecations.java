package sitcov.export;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import org.w3c.dom.Attr;
import org.w3c.dom.Element;
import org.w3c.dom.NamedNodeMap;
import org.w3c.dom.Node;

/**
 * What an ASAM OpenSCENARIO schema marks deprecated (an annotation whose appinfo reads "deprecated"), and where a
 * document uses it: an element declared deprecated where it stands, an element of a deprecated type, an attribute
 * declared deprecated, or an attribute's value that its type's enumeration marks deprecated. The document is walked
 * from its root through the schema's declarations, groups included, as a validator resolves them.
 */
final class Deprecations {
    private static final String XS = "http://www.w3.org/2001/XMLSchema";
    private final Map<String, Element> complexTypes = new HashMap<>();
    private final Map<String, Element> simpleTypes = new HashMap<>();
    private final Map<String, Element> groups = new HashMap<>();
    private final Map<String, Element> roots = new HashMap<>();

    private Deprecations(Element schema) {
        for (Node n = schema.getFirstChild(); n != null; n = n.getNextSibling()) {
            if (n instanceof Element e && XS.equals(e.getNamespaceURI())) {
                Map<String, Element> into = switch (e.getLocalName()) {
                    case "complexType" -> complexTypes;
                    case "simpleType" -> simpleTypes;
                    case "group" -> groups;
                    case "element" -> roots;
                    default -> new HashMap<>();
                };
                into.put(e.getAttribute("name"), e);
            }
        }
    }

    static Deprecations of(Path xsd) throws IOException {
        // some of the schema files begin with a byte-order mark
        return new Deprecations(Dom.parseNamespaced(Files.readString(xsd).replaceFirst("^\uFEFF", "")));
    }

    /** Every use of a deprecated construct in {@code xml}, each as a path to it and what is deprecated. */
    List<String> in(String xml) {
        Element root = Dom.parse(xml);
        List<String> out = new ArrayList<>();
        walk(root, roots.get(root.getTagName()).getAttribute("type"), root.getTagName(), out);
        return out;
    }

    private void walk(Element e, String type, String path, List<String> out) {
        Element ct = complexTypes.get(type);
        if (ct == null) {
            return;
        }
        if (deprecated(ct)) {
            out.add(path + " is a " + type + ", which is deprecated");
        }
        NamedNodeMap attributes = e.getAttributes();
        for (int i = 0; i < attributes.getLength(); i++) {
            Attr a = (Attr) attributes.item(i);
            Optional<Element> declared = declarations(ct, "attribute").stream()
                    .filter(d -> d.getAttribute("name").equals(a.getName())).findFirst();
            if (declared.isPresent() && deprecated(declared.get())) {
                out.add(path + "/@" + a.getName() + " is deprecated");
            }
            if (declared.isPresent() && deprecatedValue(declared.get().getAttribute("type"), a.getValue())) {
                out.add(path + "/@" + a.getName() + "=\"" + a.getValue() + "\" is a deprecated value");
            }
        }
        for (Node n = e.getFirstChild(); n != null; n = n.getNextSibling()) {
            if (n instanceof Element child) {
                String here = path + "/" + child.getTagName();
                Element declared = element(ct, child.getTagName())
                        .orElseThrow(() -> new AssertionError(here + " is not declared in " + type));
                if (deprecated(declared)) {
                    out.add(here + " is deprecated where it stands");
                }
                walk(child, declared.getAttribute("type"), here, out);
            }
        }
    }

    /** The declaration of the child element {@code name} in a complex type or group, through the groups it refers to. */
    private Optional<Element> element(Element content, String name) {
        for (Element d : declarations(content, "element")) {
            if (d.getAttribute("name").equals(name)) {
                return Optional.of(d);
            }
        }
        for (Element g : declarations(content, "group")) {
            Optional<Element> found = element(groups.get(g.getAttribute("ref")), name);
            if (found.isPresent()) {
                return found;
            }
        }
        return Optional.empty();
    }

    private static List<Element> declarations(Element content, String kind) {
        List<Element> out = new ArrayList<>();
        var nodes = content.getElementsByTagNameNS(XS, kind);
        for (int i = 0; i < nodes.getLength(); i++) {
            out.add((Element) nodes.item(i));
        }
        return out;
    }

    private boolean deprecatedValue(String type, String value) {
        Element st = simpleTypes.get(type);
        return st != null && declarations(st, "enumeration").stream()
                .anyMatch(v -> v.getAttribute("value").equals(value) && deprecated(v));
    }

    private static boolean deprecated(Element declaration) {
        for (Node n = declaration.getFirstChild(); n != null; n = n.getNextSibling()) {
            if (n instanceof Element a && "annotation".equals(a.getLocalName())) {
                return a.getTextContent().trim().equals("deprecated");
            }
        }
        return false;
    }
}
