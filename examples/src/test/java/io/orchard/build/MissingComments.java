package io.orchard.build;

import com.sun.source.doctree.DocCommentTree;
import com.sun.source.util.DocTrees;
import com.sun.source.util.TreePath;
import java.util.ArrayList;
import java.util.List;
import java.util.Locale;
import java.util.Set;
import javax.lang.model.SourceVersion;
import javax.lang.model.element.Element;
import javax.lang.model.element.ElementKind;
import javax.lang.model.element.TypeElement;
import javax.lang.model.util.ElementFilter;
import javax.lang.model.util.Elements;
import jdk.javadoc.doclet.Doclet;
import jdk.javadoc.doclet.DocletEnvironment;
import jdk.javadoc.doclet.Reporter;

/**
 * A doclet that writes no documentation: it lists the public and protected types and members, of
 * the sources javadoc is given, that have no doc comment at all, as doclint's "no comment" does,
 * without doclint's demand for an {@code @param} and {@code @return} on every member whose prose
 * already says it. A member that overrides another inherits its comment and needs none; members
 * the compiler writes (a record's accessors, an enum's values()) have none to give.
 */
public final class MissingComments implements Doclet {

    private static final List<String> FOUND = new ArrayList<>();
    private static final Set<ElementKind> MEMBERS = Set.of(ElementKind.METHOD, ElementKind.CONSTRUCTOR,
            ElementKind.FIELD, ElementKind.ENUM_CONSTANT);

    /** What the last run found, as {@code file:line: kind name}; taken by JavadocCoverageTest. */
    static synchronized List<String> takeFound() {
        List<String> found = List.copyOf(FOUND);
        FOUND.clear();
        return found;
    }

    @Override
    public void init(Locale locale, Reporter reporter) {
    }

    @Override
    public String getName() {
        return "MissingComments";
    }

    @Override
    public Set<? extends Option> getSupportedOptions() {
        return Set.of();
    }

    @Override
    public SourceVersion getSupportedSourceVersion() {
        return SourceVersion.latest();
    }

    @Override
    public boolean run(DocletEnvironment environment) {
        DocTrees trees = environment.getDocTrees();
        Elements elements = environment.getElementUtils();
        List<String> found = new ArrayList<>();
        for (TypeElement type : ElementFilter.typesIn(environment.getIncludedElements())) {
            check(type, trees, found);
            for (Element member : type.getEnclosedElements()) {
                if (MEMBERS.contains(member.getKind()) && environment.isIncluded(member)
                        && elements.getOrigin(member) == Elements.Origin.EXPLICIT
                        && trees.getPath(member) != null // else the compiler wrote it: a record's equals()...
                        && member.getAnnotation(Override.class) == null) {
                    check(member, trees, found);
                }
            }
        }
        synchronized (MissingComments.class) {
            FOUND.addAll(found);
        }
        return true;
    }

    private static void check(Element element, DocTrees trees, List<String> found) {
        DocCommentTree comment = trees.getDocCommentTree(element);
        if (comment != null && !comment.getFullBody().isEmpty()) {
            return;
        }
        TreePath path = trees.getPath(element);
        String where = "?";
        if (path != null) {
            var unit = path.getCompilationUnit();
            long position = trees.getSourcePositions().getStartPosition(unit, path.getLeaf());
            where = unit.getSourceFile().getName() + ":" + unit.getLineMap().getLineNumber(position);
        }
        String name = element.getKind() == ElementKind.CONSTRUCTOR
                ? element.getEnclosingElement().getSimpleName() + "(...)"
                : element.getSimpleName().toString();
        found.add(where + ": " + element.getKind().toString().toLowerCase(Locale.ROOT) + " " + name);
    }
}
